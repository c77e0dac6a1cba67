// Module choice for spatial arms: the lightest allowed module per joint
// that carries it, pitch joints loaded by the arm's weight, and the
// overload named when none does.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include <modsynth/control/joint_limits.h>
#include <modsynth/control/retime.h>
#include <modsynth/hardware/catalog.h>
#include <modsynth/hardware/dh_dynamics.h>
#include <modsynth/hardware/select_dh_modules.h>
#include <modsynth/hardware/select_modules.h>
#include <modsynth/io/solution_io.h>
#include <modsynth/io/spatial_task_io.h>
#include <modsynth/task/input_error.h>

using namespace modsynth;
using hardware::Catalog;

namespace {

const std::string kFixtures = std::string(MODSYNTH_SOURCE_DIR) + "/tests/fixtures/spatial/";

struct Planted {
    task::SpatialTask task;
    synth::Solution solution;
};

/// A planted spatial solution (a yaw column and pitch links), timed.
Planted planted(const std::string& name) {
    Planted p{io::load_spatial_task(kFixtures + name + ".task.json"),
              io::load_solution(kFixtures + name + ".planted.json").solution};
    const int n = p.solution.dh_robot->dof();
    p.solution.samples = control::retime(p.solution.samples, control::joint_limits_for(p.task, n));
    return p;
}

}  // namespace

TEST_CASE("spatial module choice: the lightest module that carries each joint", "[hardware]") {
    const Catalog catalog = hardware::load_default_catalog();
    for (const char* name : {"s3-0001", "s4-0010"}) {
        Planted p = planted(name);
        const auto& chain = *p.solution.dh_robot;
        const auto sel = hardware::select_modules(p.task, chain, p.solution.samples, catalog);
        REQUIRE(sel.checked);
        REQUIRE(static_cast<int>(sel.joints.size()) == chain.dof());
        CHECK(sel.carried());
        for (const auto& j : sel.joints) {
            const hardware::Actuator* chosen = catalog.actuator(j.module);
            REQUIRE(chosen);
            CHECK(j.carries);
            // No lighter allowed module (the default family's) would do.
            for (const hardware::Actuator* a :
                 hardware::allowed_actuators(p.task.robot.modules, catalog)) {
                if (a->mass >= chosen->mass) continue;
                const bool carries = a->peak_torque >= j.load.peak_torque &&
                                     a->continuous_torque >= j.load.rms_torque &&
                                     a->max_speed >= j.load.max_speed;
                CHECK_FALSE(carries);
            }
        }
        // The shoulder (joint 2, about a horizontal axis) holds the arm up:
        // at the first pose, at rest, it needs the static torque at least.
        const auto modules = [&] {
            std::vector<const hardware::Actuator*> m;
            for (const auto& j : sel.joints) m.push_back(catalog.actuator(j.module));
            return m;
        }();
        const auto model = hardware::dh_arm_model(p.task.robot, chain, catalog, modules);
        const std::vector<double> zero(chain.dof(), 0.0);
        const auto still =
            hardware::inverse_dynamics(model, p.solution.samples.front().q, zero, zero);
        CHECK(std::abs(still[1]) > 0.5);
        CHECK(sel.joints[1].load.peak_torque >= std::abs(still[1]));
        // The yaw joint turns about the vertical: gravity does not load it.
        CHECK(std::abs(still[0]) < 1e-9);
    }
}

TEST_CASE("spatial module choice names the overloaded joint", "[hardware]") {
    const Catalog catalog = hardware::load_default_catalog();
    Planted p = planted("s4-0010");
    p.task.robot.payload = 4.0;
    p.task.robot.modules = {"X5-1", "X5-4"};
    const auto sel =
        hardware::select_modules(p.task, *p.solution.dh_robot, p.solution.samples, catalog);
    REQUIRE(sel.checked);
    CHECK_FALSE(sel.carried());
    // Nothing allowed holds 4 kg at the tool up at the shoulder; the
    // message names the most proximal joint overloaded, with the allowed
    // module that comes closest (the stronger) and its negative margin.
    CHECK_FALSE(sel.joints[1].carries);
    CHECK(sel.joints[1].module == "X5-4");
    REQUIRE(sel.overloaded_joint >= 1);
    CHECK(sel.overloaded_joint <= 2);
    CHECK(sel.message.find("joint " + std::to_string(sel.overloaded_joint) + " is overloaded") !=
          std::string::npos);
    CHECK(sel.message.find("X5-4") != std::string::npos);
    CHECK(sel.message.find("margin -") != std::string::npos);
    // Untimed samples: nothing chosen, and the reason given.
    auto untimed = p.solution.samples;
    for (auto& s : untimed) s.qd.clear(), s.qdd.clear();
    const auto none = hardware::select_modules(p.task, *p.solution.dh_robot, untimed, catalog);
    CHECK_FALSE(none.checked);
    CHECK(none.message.find("qd, qdd") != std::string::npos);
    p.task.robot.modules = {"X9-99"};
    CHECK_THROWS_AS(
        hardware::select_modules(p.task, *p.solution.dh_robot, p.solution.samples, catalog),
        task::InputError);
}

TEST_CASE("spatial timing caps and limits follow the task", "[hardware]") {
    const Catalog catalog = hardware::load_default_catalog();
    task::SpatialTask t;
    CHECK(std::isinf(hardware::module_speed_cap(t, catalog)));
    t.robot.modules = {"X8-9", "X8-16"};
    CHECK(hardware::module_speed_cap(t, catalog) == Approx(catalog.actuator("X8-16")->max_speed));
    CHECK(std::isinf(hardware::module_speed_cap(t, std::nullopt)));
    const auto strongest = hardware::strongest_modules(t, 4, catalog);
    REQUIRE(strongest.size() == 4);
    CHECK(strongest[3]->name == "X8-16");
    t.robot.joint_limits = task::JointLimitsSpec{{1.0, 2.0, 3.0}, {4.0}};
    const auto limits = control::joint_limits_for(t, 3);
    CHECK(limits.velocity == std::vector<double>{1.0, 2.0, 3.0});
    CHECK(limits.acceleration == std::vector<double>{4.0, 4.0, 4.0});
    CHECK_THROWS_AS(control::joint_limits_for(t, 4), task::InputError);
}

TEST_CASE("spatial module choice runs across the families named and totals the cost",
          "[hardware]") {
    const Catalog catalog = hardware::load_default_catalog();
    Planted p = planted("s3-0001");
    p.task.robot.modules = {"feetech", "dynamixel-x"};
    const auto sel =
        hardware::select_modules(p.task, *p.solution.dh_robot, p.solution.samples, catalog);
    REQUIRE(sel.checked);
    double total = 0.0;
    for (const auto& j : sel.joints) {
        CHECK((j.family == "feetech" || j.family == "dynamixel-x"));
        REQUIRE(j.cost);
        total += *j.cost;
    }
    REQUIRE(sel.total_cost);
    CHECK(*sel.total_cost == Approx(total));
    CHECK(sel.cost.find("cost: ") == 0);
    CHECK(sel.cost.find(" total $") != std::string::npos);
}

namespace {

/// A printed link of `mass` kg whose centre is `com` in the frame it is
/// drawn in, with a small inertia of its own.
hardware::PrintedDhLink printed_link(int link, double mass, const geometry::Vec3& com) {
    hardware::PrintedDhLink p;
    p.link = link;
    p.part.mass = mass;
    p.part.com = com;
    p.part.inertia = mass * 1e-3 * Eigen::Matrix3d::Identity();
    return p;
}

}  // namespace

TEST_CASE("a spatial arm model carries the printed links in place of the a tubes",
          "[hardware][parts]") {
    const Catalog catalog = hardware::load_default_catalog();
    const hardware::Actuator* x5 = catalog.actuator("X5-1");
    REQUIRE(x5);
    const std::vector<const hardware::Actuator*> modules{x5, x5};
    task::SpatialRobotSpec spec;
    kinematics::DhChain chain;
    chain.link_diameter = spec.link_diameter;
    chain.rows = {{0.30, 0.0, 0.0}, {0.25, 0.0, 0.0}};
    const geometry::Vec3 c(0.14, 0.002, 0.009);
    // Link 1 is only its a part: the printed link (its tube and both
    // adapters gone) and module 2's housing on o_1.
    const auto model =
        hardware::dh_arm_model(spec, chain, catalog, modules, {printed_link(0, 0.2, c)});
    const hardware::RigidBody& body = model.links[0];
    CHECK(body.mass == Approx(0.2 + x5->mass));
    const geometry::Vec3 centre =
        (0.2 * c + x5->mass * geometry::Vec3(0.30, 0.0, 0.0)) / (0.2 + x5->mass);
    CHECK((body.com - centre).norm() < 1e-12);
    // Unprinted, the link weighs its tube and adapters too.
    const auto tubes = hardware::dh_arm_model(spec, chain, catalog, modules);
    CHECK(tubes.links[0].mass > x5->mass + catalog.adapter().mass);
    CHECK(tubes.links[1].mass == Approx(model.links[1].mass));

    // Where a link also has d and a twist, the d tube and the brackets
    // stay: what a heavier print adds is its own mass, at its centre placed
    // in the joint frame (d < 0: hanging from the output, turned over; a <
    // 0: turned about the axis).
    for (const double a : {0.30, -0.30}) {
        chain.rows = {{a, geometry::kPi / 2, -0.05}, {0.25, 0.0, 0.0}};
        const auto light =
            hardware::dh_arm_model(spec, chain, catalog, modules, {printed_link(0, 0.1, c)});
        const auto heavy =
            hardware::dh_arm_model(spec, chain, catalog, modules, {printed_link(0, 0.6, c)});
        const auto& l = light.links[0];
        const auto& h = heavy.links[0];
        CHECK(h.mass - l.mass == Approx(0.5));
        const double s = a < 0.0 ? -1.0 : 1.0;
        const geometry::Vec3 placed(s * c.x(), -s * c.y(), -0.05 - c.z());
        CHECK(((h.mass * h.com - l.mass * l.com) / 0.5 - placed).norm() < 1e-12);
        // More than the printed links: the d tube and the corner bracket.
        CHECK(l.mass > 0.1 + x5->mass + hardware::mount_part(catalog, true).mass);
    }
    chain.rows = {{0.0, geometry::kPi / 2, 0.3}, {0.25, 0.0, 0.0}};
    CHECK_THROWS_AS(
        hardware::dh_arm_model(spec, chain, catalog, modules, {printed_link(0, 0.1, c)}),
        std::invalid_argument);
}

TEST_CASE("printed links' masses enter the spatial choice in place of the tubes'",
          "[hardware][parts]") {
    const Catalog catalog = hardware::load_default_catalog();
    Planted p = planted("s3-0001");
    const auto& chain = *p.solution.dh_robot;
    const auto tubes = hardware::select_modules(p.task, chain, p.solution.samples, catalog);
    REQUIRE(tubes.carried());
    // Light printed links lower the shoulder's load (joint 2, about a
    // horizontal axis); heavy ones (3 kg at each a part's middle) raise it
    // past what the tubes needed.
    const auto with = [&](double mass) {
        std::vector<hardware::PrintedDhLink> printed;
        for (int k = 0; k < chain.dof(); ++k) {
            const double a = chain.rows[static_cast<std::size_t>(k)].a;
            if (std::abs(a) > 0.001)
                printed.push_back(
                    printed_link(k, mass, geometry::Vec3(std::abs(a) / 2, 0.0, 0.01)));
        }
        REQUIRE(printed.size() == 2);
        return hardware::select_modules(p.task, chain, p.solution.samples, catalog, printed);
    };
    const auto light = with(0.05);
    const auto heavy = with(3.0);
    CHECK(light.joints[1].load.peak_torque < tubes.joints[1].load.peak_torque);
    CHECK(heavy.joints[1].load.peak_torque > tubes.joints[1].load.peak_torque);
    CHECK(catalog.actuator(heavy.joints[1].module)->peak_torque >
          catalog.actuator(tubes.joints[1].module)->peak_torque);
}
