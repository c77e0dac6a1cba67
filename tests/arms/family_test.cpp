// Every arm family against itself: its pose (the points the refinement and
// the guesses see) is the chain of its DH rows at the joint angles its IK
// gives, the IK reaches the target on every branch it answers for, the
// pose's derivatives are those of finite differences, and a design read
// back from its chain is the design.
#include <modsynth/arms/family.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include <modsynth/geometry/vec.h>
#include <modsynth/kinematics/dh_chain.h>

using modsynth::arms::families;
using modsynth::arms::Family;
using modsynth::geometry::Vec3;
using namespace modsynth::kinematics;

namespace {

/// Every twist, so that every family has its variants.
modsynth::task::SpatialRobotSpec any_twist() {
    modsynth::task::SpatialRobotSpec spec;
    spec.twists = {0.0, modsynth::geometry::kPi / 2, -modsynth::geometry::kPi / 2};
    spec.min_link_length = 0.05;
    spec.max_link_length = 0.6;
    return spec;
}

ArmDesign random_design(const Family& family, int dof, int variant, std::mt19937& rng) {
    const auto spec = any_twist();
    std::uniform_real_distribution<double> u(0.0, 1.0);
    ArmDesign d;
    d.model = &family;
    d.link_diameter = 0.02;
    d.shape.dof = dof;
    d.shape.variant = variant;
    d.shape.base = Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);
    for (const auto& b : family.value_bounds(spec, dof, variant))
        d.shape.values.push_back(b.lower + u(rng) * (b.upper - b.lower));
    d.branches = {0};
    const int along = family.along_count(dof, variant);
    std::vector<double> numbers;
    for (int i = 0; i < 2 * along; ++i) numbers.push_back(2.0 * u(rng) - 1.0);
    d.along = {numbers};
    return d;
}

/// Where the chain's EE is for some joint angles: a target the design
/// reaches.
Vec3 reachable_target(const ArmDesign& d, std::mt19937& rng) {
    std::uniform_real_distribution<double> angle(-3.0, 3.0);
    std::vector<double> q;
    for (int k = 0; k < d.dof(); ++k) q.push_back(angle(rng));
    return end_effector(d.chain(), q);
}

}  // namespace

TEST_CASE("every arm family's pose is its chain at the angles its IK gives", "[arms]") {
    std::mt19937 rng(5);
    const PoseMargins margins;
    for (const Family* family : families()) {
        int solved = 0;
        for (int dof = 3; dof <= 6; ++dof) {
            for (int variant : family->variants(dof, any_twist())) {
                for (int trial = 0; trial < 40; ++trial) {
                    const ArmDesign d = random_design(*family, dof, variant, rng);
                    const DhChain chain = d.chain();
                    REQUIRE(chain.dof() == dof);
                    PoseTarget<double> target;
                    target.point = reachable_target(d, rng);
                    const std::vector<double> along = d.along_at(0, 0.5);
                    for (int branch = 0; branch < family->branch_count(dof); ++branch) {
                        const auto q = family->joint_angles(d, target, branch, along);
                        if (!q) continue;
                        INFO(family->name()
                             << ", " << dof << " joints, " << family->describe_variant(variant)
                             << ", branch " << branch);
                        ++solved;
                        REQUIRE(static_cast<int>(q->size()) == dof);
                        CHECK((end_effector(chain, *q) - target.point).norm() < 1e-7);
                        const auto pose = family->pose(d.shape, target, branch, along, margins);
                        const auto segments = chain_segments(chain, *q);
                        REQUIRE(pose.points.size() == segments.size() + 1);
                        REQUIRE(pose.links.size() == segments.size());
                        for (std::size_t k = 0; k < segments.size(); ++k) {
                            CHECK((pose.points[k] - segments[k].start).norm() < 1e-7);
                            CHECK((pose.points[k + 1] - segments[k].end).norm() < 1e-7);
                        }
                        const auto frames = modsynth::kinematics::frames(chain, *q);
                        REQUIRE(pose.joints.size() == static_cast<std::size_t>(dof));
                        for (int k = 0; k < dof; ++k)
                            CHECK((pose.joints[static_cast<std::size_t>(k)] -
                                   frames[static_cast<std::size_t>(k)].translation())
                                      .norm() < 1e-7);
                        for (const auto& limit : pose.limits) {
                            INFO(limit.what);
                            CHECK(std::isfinite(limit.value));
                        }
                    }
                }
            }
        }
        INFO(family->name());
        CHECK(solved > 100);
    }
}

TEST_CASE("every arm family's pose has the derivatives of finite differences", "[arms]") {
    std::mt19937 rng(9);
    const PoseMargins margins;
    for (const Family* family : families()) {
        for (int dof = 3; dof <= 5; ++dof) {
            for (int variant : family->variants(dof, any_twist())) {
                const ArmDesign d = random_design(*family, dof, variant, rng);
                PoseTarget<double> target;
                target.point = reachable_target(d, rng);
                const std::vector<double> along = d.along_at(0, 0.5);
                // The variables: base, values, free numbers.
                std::vector<double> x{d.shape.base.x(), d.shape.base.y(), d.shape.base.z()};
                x.insert(x.end(), d.shape.values.begin(), d.shape.values.end());
                x.insert(x.end(), along.begin(), along.end());
                const int n = static_cast<int>(x.size());
                const auto evaluate = [&](const std::vector<double>& v) {
                    ArmShape<double> s = d.shape;
                    s.base = Vec3(v[0], v[1], v[2]);
                    for (std::size_t k = 0; k < s.values.size(); ++k) s.values[k] = v[3 + k];
                    std::vector<double> a(v.begin() + 3 + static_cast<long>(s.values.size()),
                                          v.end());
                    return family->pose(s, target, 0, a, margins);
                };
                ArmShape<AD> s;
                s.dof = dof;
                s.variant = variant;
                std::vector<AD> ad;
                for (int i = 0; i < n; ++i) ad.emplace_back(x[static_cast<std::size_t>(i)], n, i);
                s.base = Point3<AD>(ad[0], ad[1], ad[2]);
                s.values.assign(ad.begin() + 3,
                                ad.begin() + 3 + static_cast<long>(d.shape.values.size()));
                const std::vector<AD> a(ad.begin() + 3 + static_cast<long>(d.shape.values.size()),
                                        ad.end());
                PoseTarget<AD> t;
                t.point =
                    Point3<AD>(AD(target.point.x()), AD(target.point.y()), AD(target.point.z()));
                const auto exact = family->pose(s, t, 0, a, margins);
                const auto base = evaluate(x);
                // Away from the singularities, where the floored roots bend.
                if (std::abs(base.limits.front().value) > 0.9) continue;
                INFO(family->name()
                     << ", " << dof << " joints, " << family->describe_variant(variant));
                for (int i = 0; i < n; ++i) {
                    const double h = 1e-6;
                    std::vector<double> up = x, down = x;
                    up[static_cast<std::size_t>(i)] += h;
                    down[static_cast<std::size_t>(i)] -= h;
                    const auto pu = evaluate(up), pd = evaluate(down);
                    for (std::size_t k = 0; k < base.points.size(); ++k)
                        for (int c = 0; c < 3; ++c) {
                            const double fd = (pu.points[k][c] - pd.points[k][c]) / (2.0 * h);
                            const auto& der = exact.points[k][c].derivatives();
                            const double got = i < der.size() ? der[i] : 0.0;
                            CHECK(got == Approx(fd).margin(1e-5));
                        }
                    for (std::size_t k = 0; k < base.limits.size(); ++k) {
                        const double fd = (pu.limits[k].value - pd.limits[k].value) / (2.0 * h);
                        const auto& der = exact.limits[k].value.derivatives();
                        const double got = i < der.size() ? der[i] : 0.0;
                        CHECK(got == Approx(fd).margin(1e-5));
                    }
                }
            }
        }
    }
}

TEST_CASE("a design read back from its chain is the design", "[arms]") {
    std::mt19937 rng(13);
    for (const Family* family : families()) {
        for (int dof = 3; dof <= 6; ++dof) {
            for (int variant : family->variants(dof, any_twist())) {
                const ArmDesign d = random_design(*family, dof, variant, rng);
                INFO(family->name()
                     << ", " << dof << " joints, " << family->describe_variant(variant));
                const auto read = family->read(d.chain());
                REQUIRE(read);
                CHECK(read->variant == variant);
                CHECK(read->dof == dof);
                REQUIRE(read->values.size() == d.shape.values.size());
                for (std::size_t k = 0; k < read->values.size(); ++k)
                    CHECK(read->values[k] == Approx(d.shape.values[k]));
                // No other family reads it as its own, but where the patterns
                // coincide.
                for (const Family* other : families())
                    if (other != family && other->read(d.chain()))
                        CHECK(other->read(d.chain())->dof == dof);
            }
        }
    }
}

TEST_CASE("a family builds only what robot.twists allows", "[arms]") {
    modsynth::task::SpatialRobotSpec flat;
    flat.twists = {0.0};
    modsynth::task::SpatialRobotSpec upright;
    upright.twists = {modsynth::geometry::kPi / 2};
    for (const Family* family : families()) {
        INFO(family->name());
        CHECK(family->variants(2, any_twist()).empty());
        CHECK(family->variants(7, any_twist()).empty());
        CHECK(family->variants(3, upright).empty());
        CHECK(!family->needs().empty());
    }
    const auto scara = std::find_if(families().begin(), families().end(),
                                    [](const Family* f) { return f->name() == "scara"; });
    REQUIRE(scara != families().end());
    CHECK(!(*scara)->variants(3, flat).empty());
}
