#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <modsynth/control/spatial_samples.h>
#include <modsynth/geometry/distance3.h>
#include <modsynth/io/solution_io.h>
#include <modsynth/io/spatial_task_io.h>
#include <modsynth/kinematics/yaw_pitch_ik.h>
#include <modsynth/verify/spatial_verifier.h>

#include "../support/fixtures.h"

using namespace modsynth;
using geometry::Vec3;
using verify::Violation;

namespace {

bool has(const verify::Certificate& c, Violation::Kind kind) {
    return std::any_of(c.violations.begin(), c.violations.end(),
                       [&](const Violation& v) { return v.kind == kind; });
}

std::string first_problem(const verify::Certificate& c) {
    if (!c.violations.empty()) return c.violations.front().message;
    if (!c.coarse_pairs.empty()) return "coarse pair " + std::to_string(c.coarse_pairs.front());
    return "";
}

struct Planted {
    task::SpatialTask task;
    kinematics::DhChain chain;
    std::vector<control::Sample> samples;
};

/// A planted task and solution of tests/fixtures/spatial (shared
/// grader's plant.py), with the samples' progress recovered as for any file.
Planted planted(const std::string& name) {
    const std::string dir = testing::source_path("tests/fixtures/spatial/");
    Planted p;
    p.task = io::load_spatial_task(dir + name + ".task.json");
    synth::Solution s = io::load_solution(dir + name + ".planted.json").solution;
    REQUIRE(s.dh_robot);
    io::check_solution_fits(p.task, s);
    p.chain = *s.dh_robot;
    p.samples = s.samples;
    control::recover_parameters(p.task, p.chain, p.samples);
    return p;
}

verify::Certificate certify(const Planted& p) {
    return verify::certify(p.task, p.chain, p.samples);
}

const char* const kPlanted[] = {"s3-0001", "s3-0004", "s3-0017", "s4-0010", "s4-0017", "s4-0030"};

/// The joint-linear motion replayed at `steps` sub-steps per pair: the least
/// clearance margin of the clearance parts, the least self-collision margin
/// and the largest distance of the EE from its primitive (trace pairs) or
/// transition point.
struct Replay {
    double clearance = 1e9, self = 1e9, deviation = 0.0;
};

Replay replay(const Planted& p, int steps) {
    Replay r;
    const auto layout = kinematics::segment_layout(p.chain);
    const auto parts =
        kinematics::clearance_parts(layout, p.task.robot.tool_length, p.chain.link_diameter / 2);
    const double d = p.chain.link_diameter;
    for (std::size_t i = 0; i + 1 < p.samples.size(); ++i) {
        const auto& a = p.samples[i];
        const auto& b = p.samples[i + 1];
        for (int m = 0; m <= steps; ++m) {
            const double u = double(m) / steps;
            std::vector<double> q(a.q.size());
            for (std::size_t k = 0; k < q.size(); ++k) q[k] = a.q[k] + u * (b.q[k] - a.q[k]);
            const auto segs = kinematics::chain_segments(p.chain, q);
            const Vec3 ee = kinematics::end_effector(p.chain, q);
            for (const auto& part : parts) {
                const auto& s = segs[static_cast<std::size_t>(part.segment)];
                const Vec3 x0 = s.start + part.from * (s.end - s.start);
                const Vec3 x1 = s.start + part.to * (s.end - s.start);
                for (const auto& o : p.task.obstacles)
                    r.clearance = std::min(r.clearance, geometry::segment_gap(x0, x1, o) - d / 2);
            }
            for (std::size_t k = 0; k < segs.size(); ++k) {
                for (std::size_t l = k + 2; l < segs.size(); ++l)
                    r.self =
                        std::min(r.self, geometry::segment_segment(segs[k].start, segs[k].end,
                                                                   segs[l].start, segs[l].end) -
                                             d);
                if (k + 1 < segs.size())
                    r.self = std::min(r.self,
                                      geometry::point_segment(ee, segs[k].start, segs[k].end) - d);
            }
            if (a.phase == control::Phase::Trace && b.phase == control::Phase::Trace &&
                a.primitive == b.primitive) {
                const auto& prim = p.task.trajectory[control::primitive_index(p.task, a)];
                r.deviation = std::max(r.deviation, geometry::nearest(prim, ee).distance);
            }
        }
    }
    return r;
}

}  // namespace

TEST_CASE("the planted spatial solutions are certified", "[verify]") {
    for (const char* name : kPlanted) {
        const Planted p = planted(name);
        const auto cert = certify(p);
        INFO(name << ": " << first_problem(cert));
        CHECK(cert.ok);
        CHECK(cert.max_deviation < 1e-3);
        CHECK(cert.max_joint_step <= 0.008 + 1e-9);
        CHECK(cert.min_self_clearance > 0.0);
        if (!p.task.obstacles.empty()) CHECK(cert.min_clearance > 0.0);
    }
}

TEST_CASE("the spatial certificate bounds the replayed motion", "[verify]") {
    // Soundness of the between-sample bounds: the certified minima are
    // below, and the certified deviation above, what a dense replay sees.
    for (const char* name : kPlanted) {
        const Planted p = planted(name);
        const auto cert = certify(p);
        const Replay r = replay(p, 16);
        INFO(name);
        CHECK(cert.min_self_clearance <= r.self + 1e-12);
        if (!p.task.obstacles.empty()) CHECK(cert.min_clearance <= r.clearance + 1e-12);
        CHECK(cert.max_deviation >= r.deviation - 1e-12);
        // And not far below: the bounds cost little at these steps.
        CHECK(cert.min_self_clearance >= r.self - 2e-3);
        if (!p.task.obstacles.empty()) CHECK(cert.min_clearance >= r.clearance - 2e-3);
    }
}

TEST_CASE("mutated spatial solutions are refused", "[verify]") {
    const Planted base = planted("s3-0004");
    REQUIRE(certify(base).ok);
    SECTION("a link shortened: the EE leaves the path") {
        Planted p = base;
        p.chain.rows[2].a *= 0.99;
        const auto c = certify(p);
        CHECK_FALSE(c.ok);
        CHECK(has(c, Violation::Kind::Deviation));
    }
    SECTION("a sample moved") {
        Planted p = base;
        p.samples[p.samples.size() / 2].q[1] += 0.005;
        const auto c = certify(p);
        CHECK_FALSE(c.ok);
        CHECK(has(c, Violation::Kind::Deviation));
    }
    SECTION("a joint jumps between samples") {
        Planted p = base;
        for (std::size_t i = p.samples.size() / 2; i < p.samples.size(); ++i)
            p.samples[i].q[0] += 0.02 * (i == p.samples.size() / 2 ? 1.0 : 0.0);
        CHECK(has(certify(p), Violation::Kind::JointStep));
    }
    SECTION("an obstacle moved onto the chain") {
        Planted p = base;
        const auto segs = kinematics::chain_segments(p.chain, p.samples[10].q);
        const Vec3 mid = 0.5 * (segs[1].start + segs[1].end);
        p.task.obstacles.push_back(geometry::Sphere{mid + Vec3(0, 0, 0.02), 0.01});
        const auto c = certify(p);
        CHECK_FALSE(c.ok);
        CHECK(has(c, Violation::Kind::Clearance));
        CHECK(std::any_of(c.violations.begin(), c.violations.end(), [&](const Violation& v) {
            return v.obstacle == static_cast<int>(p.task.obstacles.size()) - 1 && v.link == 1;
        }));
    }
    SECTION("a twist the task does not allow") {
        Planted p = base;
        p.task.robot.twists = {0.0, -geometry::kPi / 2};
        CHECK(has(certify(p), Violation::Kind::Structure));
    }
    SECTION("a base outside the base regions") {
        Planted p = base;
        p.chain.base.z() += 0.5;
        CHECK(has(certify(p), Violation::Kind::Structure));
    }
    SECTION("a link longer than allowed") {
        Planted p = base;
        p.task.robot.max_link_length = 0.2;
        CHECK(has(certify(p), Violation::Kind::Structure));
    }
    SECTION("a tool longer than the last segment") {
        Planted p = base;
        p.task.robot.tool_length = p.chain.rows[2].a + 0.01;
        CHECK(has(certify(p), Violation::Kind::Structure));
    }
    SECTION("a joint count the task does not allow") {
        Planted p = base;
        p.task.robot.dof = {4, 5};
        CHECK(has(certify(p), Violation::Kind::Structure));
    }
    SECTION("a negative a") {
        Planted p = base;
        p.chain.rows[1].a = -p.chain.rows[1].a;
        CHECK(has(certify(p), Violation::Kind::Structure));
    }
    SECTION("a primitive traced backwards") {
        Planted p = base;
        std::reverse(p.samples.begin(), p.samples.end());
        CHECK(has(certify(p), Violation::Kind::Order));
    }
}

TEST_CASE("the tool may touch obstacles, the rest of the chain may not", "[verify]") {
    Planted p = planted("s3-0004");
    REQUIRE(p.task.robot.tool_length > 0.0);
    // An obstacle on the tool, near the EE, at every sample: clear of the
    // path itself but inside the tool's stretch.
    const auto segs = kinematics::chain_segments(p.chain, p.samples.front().q);
    const Vec3 at = segs.back().end + 0.5 * p.task.robot.tool_length *
                                          (segs.back().start - segs.back().end).normalized();
    p.task.obstacles = {geometry::Sphere{at, 0.002}};
    verify::Certificate c = certify(p);
    INFO(first_problem(c));
    CHECK_FALSE(has(c, Violation::Kind::Clearance));
    // Without the tool the same obstacle is a collision.
    p.task.robot.tool_length = 0.0;
    c = certify(p);
    CHECK(has(c, Violation::Kind::Clearance));
}

TEST_CASE("a folded arm is a self-collision", "[verify]") {
    // A yaw-pitch arm whose forearm folds back onto its upper arm; the task
    // is the arc its EE traces while the column turns, so only the fold is
    // wrong.
    kinematics::YawPitchArm arm;
    arm.column = 0.4;
    arm.links = {0.3, 0.25};
    const kinematics::DhChain chain = kinematics::to_chain(arm, 0.03175);
    auto motion = [&](double q3) {
        std::vector<control::Sample> samples;
        for (int i = 0; i <= 20; ++i) {
            control::Sample s;
            s.q = {0.005 * i, 0.3, q3};
            samples.push_back(s);
        }
        const Vec3 start = kinematics::end_effector(chain, samples.front().q);
        const Vec3 end = kinematics::end_effector(chain, samples.back().q);
        task::SpatialTask t;
        t.trajectory.push_back(
            geometry::make_arc3(start, end, Vec3(0, 0, start.z()), Vec3(0, 0, 1), true));
        control::recover_parameters(t, chain, samples);
        return std::pair{t, samples};
    };
    auto [open, open_samples] = motion(1.2);
    const auto ok = verify::certify(open, chain, open_samples);
    INFO(first_problem(ok));
    CHECK(ok.ok);
    auto [folded, folded_samples] = motion(3.05);
    const auto bad = verify::certify(folded, chain, folded_samples);
    CHECK(has(bad, Violation::Kind::SelfCollision));
}

TEST_CASE("spatial certificates are lower bounds on random travels", "[verify]") {
    // Two one-primitive strokes (each EE arc traced by turning the column)
    // joined by a joint-linear travel between random poses of a random
    // chain, with random obstacles near it: whatever is certified, the
    // certified margins never exceed the replayed ones.
    std::mt19937 rng(91);
    std::uniform_real_distribution<double> angle(-2.5, 2.5);
    std::uniform_real_distribution<double> len(0.1, 0.5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int certified = 0;
    for (int trial = 0; trial < 60; ++trial) {
        kinematics::DhChain chain;
        chain.link_diameter = 0.02;
        chain.rows = {{0.0, geometry::kPi / 2, len(rng)}};
        const int n = 3 + trial % 4;
        const double twists[] = {0.0, geometry::kPi / 2, -geometry::kPi / 2};
        for (int k = 1; k < n; ++k)
            chain.rows.push_back({len(rng), twists[rng() % 3], rng() % 2 ? 0.0 : 0.2 * len(rng)});
        std::vector<double> qa, qb;
        for (int k = 0; k < n; ++k) {
            qa.push_back(angle(rng));
            qb.push_back(qa.back() + 0.6 * (unit(rng) - 0.5));
        }
        Planted p;
        p.chain = chain;
        p.task.robot.dof = {n};
        p.task.robot.min_link_length = 0.0;
        p.task.robot.link_diameter = chain.link_diameter;
        auto stroke = [&](const std::vector<double>& q, int s) {
            std::vector<control::Sample> out;
            for (int i = 0; i <= 4; ++i) {
                control::Sample x;
                x.q = q;
                x.q[0] += 0.005 * i;
                x.stroke = s;
                out.push_back(x);
            }
            const Vec3 start = kinematics::end_effector(chain, out.front().q);
            const Vec3 end = kinematics::end_effector(chain, out.back().q);
            p.task.trajectory.push_back(
                geometry::make_arc3(start, end, Vec3(0, 0, start.z()), Vec3(0, 0, 1), true));
            return out;
        };
        p.task.stroke_starts = {0, 1};
        auto first = stroke(qa, 0);
        const std::vector<double> from = first.back().q;
        auto second = stroke(qb, 1);
        p.samples = first;
        const int steps = 80;
        for (int i = 1; i < steps; ++i) {
            control::Sample x;
            x.phase = control::Phase::Travel;
            x.stroke = 0;
            for (int k = 0; k < n; ++k)
                x.q.push_back(
                    from[static_cast<std::size_t>(k)] +
                    (qb[static_cast<std::size_t>(k)] - from[static_cast<std::size_t>(k)]) * i /
                        steps);
            p.samples.push_back(x);
        }
        p.samples.insert(p.samples.end(), second.begin(), second.end());
        // Obstacles near a pose of the travel.
        const auto segs = kinematics::chain_segments(chain, p.samples[p.samples.size() / 2].q);
        for (int o = 0; o < 3; ++o) {
            const auto& s = segs[rng() % segs.size()];
            const Vec3 x = s.start + unit(rng) * (s.end - s.start);
            const Vec3 off(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5);
            const Vec3 c = x + 0.06 * off.normalized() * (0.5 + unit(rng));
            if (o == 0) p.task.obstacles.push_back(geometry::Sphere{c, 0.02});
            if (o == 1) p.task.obstacles.push_back(geometry::Capsule{c, c + Vec3(0, 0, 0.1), 0.01});
            if (o == 2) p.task.obstacles.push_back(geometry::Box3{c, c + Vec3(0.05, 0.05, 0.05)});
        }
        control::recover_parameters(p.task, chain, p.samples);
        const auto cert = certify(p);
        const Replay r = replay(p, 24);
        INFO("trial " << trial << ": " << first_problem(cert));
        CHECK(cert.min_clearance <= r.clearance + 1e-12);
        CHECK(cert.min_self_clearance <= r.self + 1e-12);
        if (cert.ok) {
            ++certified;
            CHECK(r.clearance >= -1e-12);
            CHECK(r.self >= -1e-12);
        }
    }
    CHECK(certified > 5);
}

namespace {

/// The least of tolerance - angle over a dense replay of every pair of
/// trace samples of a primitive with a tool axis (formats.md rule 6).
double replayed_tool_margin(const Planted& p, int steps) {
    double least = 1e9;
    for (std::size_t i = 0; i + 1 < p.samples.size(); ++i) {
        const auto& a = p.samples[i];
        const auto& b = p.samples[i + 1];
        if (a.phase != control::Phase::Trace || b.phase != control::Phase::Trace ||
            a.primitive != b.primitive || a.stroke != b.stroke)
            continue;
        const int j = control::primitive_index(p.task, a);
        for (int m = 0; m <= steps; ++m) {
            const double u = double(m) / steps;
            std::vector<double> q(a.q.size());
            for (std::size_t k = 0; k < q.size(); ++k) q[k] = a.q[k] + u * (b.q[k] - a.q[k]);
            const auto segs = kinematics::chain_segments(p.chain, q);
            const Vec3 tool = (segs.back().end - segs.back().start).normalized();
            const auto wanted = task::wanted_tool(p.task, j, segs.back().end);
            REQUIRE(wanted);
            const double angle = std::acos(std::clamp(tool.dot(wanted->direction), -1.0, 1.0));
            least = std::min(least, wanted->tolerance - angle);
        }
    }
    return least;
}

const char* const kPlantedTools[] = {"std-0001", "stn-0001", "stt-0001"};

}  // namespace

TEST_CASE("planted solutions that hold a tool axis are certified, with its margin", "[verify]") {
    for (const char* name : kPlantedTools) {
        const Planted p = planted(name);
        REQUIRE(task::holds_tool(p.task));
        const auto cert = certify(p);
        INFO(name << ": " << first_problem(cert));
        CHECK(cert.ok);
        // A lower bound on what a dense replay sees, and not far below it.
        const double replayed = replayed_tool_margin(p, 16);
        CHECK(cert.min_tool_angle_margin >= 0.0);
        CHECK(cert.min_tool_angle_margin <= replayed + 1e-9);
        CHECK(cert.min_tool_angle_margin >= replayed - 0.02);
    }
}

TEST_CASE("a tool pointing off its wanted direction is refused", "[verify]") {
    SECTION("a fixed direction turned by twice its tolerance") {
        Planted p = planted("stn-0001");
        REQUIRE(p.task.tool_axis);
        auto& axis = *p.task.tool_axis;
        const Vec3 u = axis.direction.normalized();
        const Vec3 side = u.unitOrthogonal();
        axis.direction = std::cos(2 * axis.tolerance) * u + std::sin(2 * axis.tolerance) * side;
        const auto c = certify(p);
        CHECK_FALSE(c.ok);
        CHECK(has(c, Violation::Kind::ToolAxis));
        CHECK(c.min_tool_angle_margin < 0.0);
    }
    SECTION("toward the axis wanted away from it") {
        Planted p = planted("stt-0001");
        for (auto& a : p.task.tool_axes)
            if (a) a->kind = task::ToolAxis::Kind::AwayFromAxis;
        const auto c = certify(p);
        CHECK(has(c, Violation::Kind::ToolAxis));
    }
    SECTION("without a tool axis the same motion has no tool figure") {
        Planted p = planted("std-0001");
        p.task.tool_axis.reset();
        p.task.tool_axes.clear();
        const auto c = certify(p);
        CHECK(c.ok);
        CHECK(std::isinf(c.min_tool_angle_margin));
    }
}
