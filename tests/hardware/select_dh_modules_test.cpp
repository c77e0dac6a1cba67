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
