#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include <modsynth/hardware/catalog.h>
#include <modsynth/hardware/dynamics.h>
#include <modsynth/hardware/select_modules.h>
#include <modsynth/task/input_error.h>

using namespace modsynth::hardware;
using modsynth::control::Sample;

namespace {

Catalog shipped() { return load_catalog(std::string(MODSYNTH_SOURCE_DIR) + "/catalog"); }

modsynth::kinematics::Robot arm() {
    modsynth::kinematics::Robot r;
    r.link_lengths = {0.40, 0.35};
    r.link_diameter = 0.03175;
    return r;
}

/// Joint k swings as a_k sin(w t) about b_k for 2 s: rates and
/// accelerations in closed form.
std::vector<Sample> swing(double w) {
    const double a[2] = {0.8, 0.6}, b[2] = {0.2, 1.0};
    std::vector<Sample> out;
    for (int i = 0; i <= 400; ++i) {
        Sample s;
        s.t = 0.005 * i;
        for (int k = 0; k < 2; ++k) {
            s.q.push_back(b[k] + a[k] * std::sin(w * s.t));
            s.qd.push_back(a[k] * w * std::cos(w * s.t));
            s.qdd.push_back(-a[k] * w * w * std::sin(w * s.t));
        }
        out.push_back(s);
    }
    return out;
}

}  // namespace

TEST_CASE("a light, slow motion gets the lightest modules", "[hardware]") {
    const Catalog c = shipped();
    modsynth::task::Task task;
    const auto sel = select_modules(task, arm(), swing(1.0), c);
    REQUIRE(sel.checked);
    CHECK(sel.carried());
    REQUIRE(sel.joints.size() == 2);
    CHECK(sel.joints[0].module == "X5-1");
    CHECK(sel.joints[1].module == "X5-1");
    CHECK(sel.total_mass == Approx(2 * c.actuator("X5-1")->mass));
    for (const auto& j : sel.joints) {
        CHECK(j.carries);
        CHECK(j.peak_margin > 0.0);
        CHECK(j.continuous_margin >= 0.0);
        CHECK(j.load.rms_torque <= j.load.peak_torque);
    }
    CHECK(sel.message.find("X5-1, X5-1") != std::string::npos);
}

TEST_CASE("loads agree with inverse dynamics at the peak", "[hardware]") {
    const Catalog c = shipped();
    modsynth::task::Task task;
    task.robot.payload = 0.5;
    task.robot.gravity = modsynth::geometry::Vec2(0.0, -9.81);
    const auto samples = swing(1.5);
    const auto robot = arm();
    const std::vector<const Actuator*> modules(2, c.actuator("X8-9"));
    const ArmModel m = arm_model(task.robot, robot, c, modules);
    const auto loads = joint_loads(m, samples);
    double peak = 0.0;
    for (const auto& s : samples)
        peak = std::max(peak, std::fabs(inverse_dynamics(m, s.q, s.qd, s.qdd)[0]));
    CHECK(loads[0].peak_torque == Approx(peak));
    CHECK(loads[0].max_speed == Approx(0.8 * 1.5).epsilon(1e-3));
    CHECK(loads[0].rms_torque < loads[0].peak_torque);
}

TEST_CASE("a heavy payload in an upright plane needs stronger modules inward", "[hardware]") {
    const Catalog c = shipped();
    modsynth::task::Task task;
    task.robot.payload = 1.0;
    task.robot.gravity = modsynth::geometry::Vec2(0.0, -9.81);
    const auto sel = select_modules(task, arm(), swing(0.5), c);
    REQUIRE(sel.carried());
    // Joint 1 holds both links and the payload at up to 0.75 m.
    CHECK(sel.joints[0].load.peak_torque > sel.joints[1].load.peak_torque);
    CHECK(c.actuator(sel.joints[0].module)->peak_torque >= sel.joints[0].load.peak_torque);
    CHECK(c.actuator(sel.joints[0].module)->mass >= c.actuator(sel.joints[1].module)->mass);
    // No lighter allowed module would do at joint 1.
    for (const auto& a : c.actuators) {
        if (a.mass < sel.joints[0].mass) {
            CHECK((a.peak_torque < sel.joints[0].load.peak_torque ||
                   a.continuous_torque < sel.joints[0].load.rms_torque ||
                   a.max_speed < sel.joints[0].load.max_speed));
        }
    }
}

TEST_CASE("an overloaded joint is named with its module, time and margin", "[hardware]") {
    const Catalog c = shipped();
    modsynth::task::Task task;
    task.robot.payload = 10.0;
    task.robot.gravity = modsynth::geometry::Vec2(0.0, -9.81);
    task.robot.modules = {"X8-9", "X5-4"};
    const auto sel = select_modules(task, arm(), swing(0.5), c);
    REQUIRE(sel.checked);
    CHECK_FALSE(sel.carried());
    CHECK(sel.overloaded_joint == 1);  // the most proximal overloaded joint
    const auto& j = sel.joints[0];
    CHECK(j.module == "X8-9");  // the one with the most room
    CHECK_FALSE(j.carries);
    CHECK(j.worst_share < 0.0);
    CHECK(sel.message.find("joint 1 is overloaded") == 0);
    CHECK(sel.message.find("X8-9") != std::string::npos);
    CHECK(sel.message.find("margin -") != std::string::npos);
}

TEST_CASE("the allowed list restricts the choice and unknown names are refused", "[hardware]") {
    const Catalog c = shipped();
    modsynth::task::Task task;
    task.robot.modules = {"X8-16", "X8-3"};
    const auto sel = select_modules(task, arm(), swing(1.0), c);
    CHECK(sel.joints[0].module == "X8-3");  // the lighter of the two
    task.robot.modules = {"X8-9", "X9-1"};
    CHECK_THROWS_WITH(select_modules(task, arm(), swing(1.0), c),
                      Catch::StartsWith("robot.modules[1]: the module catalog has no \"X9-1\""));
}

TEST_CASE("an untimed motion is not checked", "[hardware]") {
    auto samples = swing(1.0);
    for (auto& s : samples) s.qd.clear();
    modsynth::task::Task task;
    const auto sel = select_modules(task, arm(), samples, shipped());
    CHECK_FALSE(sel.checked);
    CHECK_FALSE(sel.carried());
    CHECK(sel.message.find("qd, qdd") != std::string::npos);
}

TEST_CASE("printed links' masses enter the choice in place of the tubes'", "[hardware][parts]") {
    const Catalog c = shipped();
    modsynth::task::Task task;
    task.robot.gravity = modsynth::geometry::Vec2(0.0, -9.81);
    const auto tubes = select_modules(task, arm(), swing(0.5), c);
    REQUIRE(tubes.carried());
    // Light printed links lower joint 1's gravity load; heavy ones (5 kg at
    // each link's middle) raise it past what the tubes needed.
    const auto r = arm().link_lengths;
    const auto with = [&](double mass) {
        return select_modules(task, arm(), swing(0.5), c,
                              {{mass, r[0] / 2, 0.0}, {mass, r[1] / 2, 0.0}});
    };
    const auto light = with(0.05);
    const auto heavy = with(5.0);
    CHECK(light.joints[0].load.peak_torque < tubes.joints[0].load.peak_torque);
    CHECK(heavy.joints[0].load.peak_torque > tubes.joints[0].load.peak_torque);
    CHECK(c.actuator(heavy.joints[0].module)->peak_torque >
          c.actuator(tubes.joints[0].module)->peak_torque);
}
