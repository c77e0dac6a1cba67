// The spatial arm's dynamics (KDL's recursive Newton-Euler behind
// hardware/dh_dynamics.h) against what the bodies of the model imply,
// computed here without KDL: a horizontal arm's static torques by hand,
// gravity torques as the gradient of the potential energy, and the power
// the joints put in as the rate of change of the arm's energy.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include <modsynth/hardware/catalog.h>
#include <modsynth/hardware/dh_arm_model.h>
#include <modsynth/hardware/dh_dynamics.h>
#include <modsynth/hardware/dh_stack.h>

using namespace modsynth::hardware;
using modsynth::geometry::kPi;
using modsynth::geometry::Vec3;
using modsynth::kinematics::DhChain;
using modsynth::kinematics::DhRow;

namespace {

Catalog shipped() { return load_catalog(std::string(MODSYNTH_SOURCE_DIR) + "/catalog"); }

/// The joint frames (dh_stack.h) in the task frame: frame k - 1 turned by q_k.
std::vector<Eigen::Isometry3d> joint_frames(const DhChain& c, const std::vector<double>& q) {
    const auto f = modsynth::kinematics::frames(c, q);
    std::vector<Eigen::Isometry3d> out;
    for (std::size_t k = 0; k < q.size(); ++k)
        out.push_back(f[k] * Eigen::AngleAxisd(q[k], Eigen::Vector3d::UnitZ()));
    return out;
}

/// Kinetic plus potential energy of the model's bodies.
double energy(const DhArmModel& m, const std::vector<double>& q, const std::vector<double>& qd) {
    const auto J = joint_frames(m.chain, q);
    double e = 0.0;
    Vec3 omega = Vec3::Zero();
    for (std::size_t k = 0; k < q.size(); ++k) {
        omega += qd[k] * J[k].linear().col(2);
        const RigidBody& b = m.links[k];
        const Vec3 c = J[k] * b.com;
        Vec3 v = Vec3::Zero();
        for (std::size_t j = 0; j <= k; ++j)
            v += qd[j] * J[j].linear().col(2).cross(c - J[j].translation());
        const Eigen::Matrix3d I = J[k].linear() * b.inertia * J[k].linear().transpose();
        e +=
            0.5 * b.mass * v.squaredNorm() + 0.5 * omega.dot(I * omega) - b.mass * m.gravity.dot(c);
    }
    return e;
}

DhChain random_chain(std::mt19937& rng, int n) {
    std::uniform_real_distribution<double> len(0.05, 0.6), coord(-0.5, 0.5);
    const double twists[] = {0.0, kPi / 2, -kPi / 2, 0.7};
    DhChain c;
    c.base = Vec3(coord(rng), coord(rng), coord(rng));
    c.link_diameter = 0.03175;
    for (int k = 0; k < n; ++k) {
        DhRow r{len(rng), twists[rng() % 4], coord(rng)};
        if (rng() % 3 == 0) r.a = 0.0;
        if (rng() % 3 == 0) r.d = 0.0;
        c.rows.push_back(r);
    }
    return c;
}

DhArmModel random_model(std::mt19937& rng, const Catalog& catalog, int n) {
    modsynth::task::SpatialRobotSpec spec;
    spec.payload = 0.3 * (rng() % 3);
    spec.tool_length = (rng() % 2) ? 0.02 : 0.0;
    std::vector<const Actuator*> modules;
    for (int k = 0; k < n; ++k)
        modules.push_back(&catalog.actuators[rng() % catalog.actuators.size()]);
    return dh_arm_model(spec, random_chain(rng, n), catalog, modules);
}

std::vector<double> random_vector(std::mt19937& rng, int n, double scale) {
    std::uniform_real_distribution<double> u(-scale, scale);
    std::vector<double> v;
    for (int k = 0; k < n; ++k) v.push_back(u(rng));
    return v;
}

}  // namespace

TEST_CASE("spatial dynamics: a horizontal arm's static torques by hand", "[hardware]") {
    // A yaw column (alpha = pi/2) then two pitch links; at q = (0, 0, 0)
    // the pitch links point along +x, level.
    DhArmModel m;
    m.chain.base = Vec3(0.1, 0.2, 0.0);
    m.chain.link_diameter = 0.03;
    m.chain.rows = {{0.0, kPi / 2, 0.3}, {0.4, 0.0, 0.0}, {0.3, 0.0, 0.0}};
    m.links.resize(3);
    add_part(m.links[0], 2.0, Vec3(0.0, 0.0, 0.15));  // the column: on the yaw axis
    add_part(m.links[1], 1.0, Vec3(0.2, 0.0, 0.0));   // link 2's middle
    add_part(m.links[1], 0.5, Vec3(0.4, 0.0, 0.0));   // module 3 at its end
    add_part(m.links[2], 0.25, Vec3(0.3, 0.0, 0.0));  // payload at the EE
    const double g = 9.81;
    const auto level = inverse_dynamics(m, {0.0, 0.0, 0.0}, {0, 0, 0}, {0, 0, 0});
    // Joint 2's axis z_1 is -y after the twist: lifting the links (q_2 up)
    // raises the masses, so each pitch joint holds the weight beyond it
    // times its horizontal reach with a positive torque.
    CHECK(level[1] == Approx(g * (1.0 * 0.2 + 0.5 * 0.4 + 0.25 * 0.7)));
    CHECK(level[2] == Approx(g * 0.25 * 0.3));
    CHECK(level[0] == Approx(0.0).margin(1e-12));  // a vertical axis carries no weight
    // Pointing straight up, nothing but the bearings carries the weight.
    const auto up = inverse_dynamics(m, {0.0, kPi / 2, 0.0}, {0, 0, 0}, {0, 0, 0});
    CHECK(up[1] == Approx(0.0).margin(1e-12));
    CHECK(up[2] == Approx(0.0).margin(1e-12));
    // Gravity along the yaw axis' perpendicular loads the yaw joint too.
    m.gravity = Vec3(0.0, -g, 0.0);
    const auto sideways = inverse_dynamics(m, {0.0, 0.0, 0.0}, {0, 0, 0}, {0, 0, 0});
    CHECK(sideways[0] == Approx(g * (1.0 * 0.2 + 0.5 * 0.4 + 0.25 * 0.7)));
    CHECK_THROWS_AS(inverse_dynamics(m, {0.0}, {0, 0, 0}, {0, 0, 0}), std::invalid_argument);
}

TEST_CASE("spatial dynamics: gravity torques are the potential energy's gradient", "[hardware]") {
    const Catalog catalog = shipped();
    std::mt19937 rng(7);
    for (int trial = 0; trial < 60; ++trial) {
        const int n = 3 + trial % 4;
        const DhArmModel m = random_model(rng, catalog, n);
        const auto q = random_vector(rng, n, 3.0);
        const std::vector<double> zero(n, 0.0);
        const auto tau = inverse_dynamics(m, q, zero, zero);
        for (int k = 0; k < n; ++k) {
            auto qp = q, qm = q;
            const double h = 1e-6;
            qp[k] += h;
            qm[k] -= h;
            const double gradient = (energy(m, qp, zero) - energy(m, qm, zero)) / (2.0 * h);
            CHECK(tau[k] == Approx(gradient).margin(1e-6));
        }
    }
}

TEST_CASE("spatial dynamics: the joints' power is the rate of change of the arm's energy",
          "[hardware]") {
    // With qd = e_k, tau_k = (M qdd)_k + (1/2) e_k' dM/dt e_k + G_k is what
    // d/dt of the energy along q(t) = q + e_k t + qdd t^2 / 2 gives: over
    // random qdd this checks every row of the mass matrix.
    const Catalog catalog = shipped();
    std::mt19937 rng(11);
    for (int trial = 0; trial < 60; ++trial) {
        const int n = 3 + trial % 4;
        const DhArmModel m = random_model(rng, catalog, n);
        const auto q = random_vector(rng, n, 3.0);
        const auto qdd = random_vector(rng, n, 5.0);
        for (int k = 0; k < n; ++k) {
            std::vector<double> qd(n, 0.0);
            qd[k] = 1.3;
            const auto at = [&](double t) {
                std::vector<double> qt(n), qdt(n);
                for (int j = 0; j < n; ++j) {
                    qt[j] = q[j] + qd[j] * t + 0.5 * qdd[j] * t * t;
                    qdt[j] = qd[j] + qdd[j] * t;
                }
                return energy(m, qt, qdt);
            };
            const double h = 1e-5;
            const double power = (at(h) - at(-h)) / (2.0 * h);
            const auto tau = inverse_dynamics(m, q, qd, qdd);
            CHECK(tau[k] * qd[k] == Approx(power).margin(1e-6));
        }
    }
}

TEST_CASE("the spatial arm model holds every part once, and the stack's cuts", "[hardware]") {
    const Catalog c = shipped();
    modsynth::task::SpatialRobotSpec spec;
    spec.payload = 0.2;
    spec.tool_length = 0.05;
    DhChain chain;
    chain.link_diameter = spec.link_diameter;
    // A yaw column, a link with both d and a (a corner), and a pitch link.
    chain.rows = {{0.0, kPi / 2, 0.40}, {0.30, 0.0, 0.10}, {0.25, 0.0, 0.0}};
    const DhStack stack = dh_stack(spec, chain);
    REQUIRE(stack.tubes.size() == 4);
    REQUIRE(stack.corners == std::vector<int>{1});
    REQUIRE(stack.mounts.size() == 2);
    CHECK(stack.mounts[0].kind == DhMountKind::RightAngleBracket);
    CHECK(stack.mounts[1].kind == DhMountKind::TubeAdapter);
    const double H = spec.module_height, W = spec.module_width, L = spec.module_length;
    const double A = spec.adapter_length, D = spec.link_diameter;
    // The column leaves module 1's output face and meets module 2, whose
    // housing lies across it (its width along the column after the twist).
    CHECK(stack.tubes[0].proximal_allowance == Approx(H / 2 + A));
    CHECK(stack.tubes[0].distal_allowance == Approx(W / 2 + A));
    CHECK(stack.tubes[0].cut_length == Approx(0.40 - H / 2 - W / 2 - 2 * A));
    // Link 2's d tube ends at the corner bracket, its a tube starts there
    // and runs into module 3's housing along its length.
    CHECK(stack.tubes[1].distal_allowance == Approx(D / 2 + A));
    CHECK(stack.tubes[2].proximal_allowance == Approx(D / 2 + A));
    CHECK(stack.tubes[2].distal_allowance == Approx(L / 2 + A));
    // The last tube ends where the tool begins.
    CHECK(stack.tubes[3].last);
    CHECK(stack.tubes[3].proximal_allowance == Approx(W / 2 + A));
    CHECK(stack.tubes[3].distal_allowance == Approx(0.05));

    const Actuator* x8 = c.actuator("X8-9");
    const Actuator* x5 = c.actuator("X5-4");
    const DhArmModel m = dh_arm_model(spec, chain, c, {x8, x8, x5});
    double total = 0.0;
    for (const auto& b : m.links) total += b.mass;
    double tubes = 0.0;
    for (const auto& t : stack.tubes) tubes += c.tube_closest_to(D).mass_per_metre * t.cut_length;
    const double bracket = c.adapter("right-angle bracket")->mass;
    const double adapter = c.adapter().mass;
    const double tool = c.tube_closest_to(spec.ee_rod_diameter).mass_per_metre * 0.05;
    // Modules 2 and 3; the mount bracket and the corner bracket; an adapter
    // at each module output (3) and at module 3's mount (1).
    CHECK(total == Approx(x8->mass + x5->mass + tubes + 2 * bracket + 4 * adapter + tool + 0.2));
    CHECK(m.gravity == Vec3(0.0, 0.0, -9.81));
    CHECK_THROWS_AS(dh_arm_model(spec, chain, c, {x8}), std::invalid_argument);
}

TEST_CASE("mount kinds follow the twist", "[hardware]") {
    CHECK(mount_kind(0.0) == DhMountKind::TubeAdapter);
    CHECK(mount_kind(kPi) == DhMountKind::TubeAdapter);
    CHECK(mount_kind(-kPi / 2) == DhMountKind::RightAngleBracket);
    CHECK(mount_kind(kPi / 2 + 1e-9) == DhMountKind::RightAngleBracket);
    CHECK(mount_kind(0.7) == DhMountKind::OtherBracket);
    CHECK(box_exit(Vec3(1.0, 2.0, 3.0), Vec3(0.0, 0.0, -1.0)) == Approx(3.0));
    CHECK(box_exit(Vec3(1.0, 2.0, 3.0), Vec3(1.0, 1.0, 0.0).normalized()) ==
          Approx(std::sqrt(2.0)));
}
