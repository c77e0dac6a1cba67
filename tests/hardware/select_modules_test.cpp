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
    for (const Actuator* a : allowed_actuators(task.robot, c)) {
        if (a->mass < sel.joints[0].mass) {
            CHECK((a->peak_torque < sel.joints[0].load.peak_torque ||
                   a->continuous_torque < sel.joints[0].load.rms_torque ||
                   a->max_speed < sel.joints[0].load.max_speed));
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

TEST_CASE("robot.modules names models or whole families", "[hardware]") {
    const Catalog c = shipped();
    const auto names = [&](const std::vector<std::string>& modules) {
        std::vector<std::string> out;
        for (const Actuator* a : allowed_actuators(modules, c)) out.push_back(a->name);
        return out;
    };
    // A family brings all its models, lightest first.
    const auto dynamixels = names({"dynamixel-x"});
    REQUIRE(dynamixels.size() == 7);
    CHECK(dynamixels.front() == "XL330-M288");
    CHECK(dynamixels.back() == "XM540-W270");
    // A model named beside its family is allowed once.
    CHECK(names({"feetech", "STS3215"}) ==
          std::vector<std::string>{"SCS0009", "STS3215", "STS3250"});
    CHECK(names({"STS3215", "X5-1"}) == std::vector<std::string>{"STS3215", "X5-1"});
    // Without robot.modules: the default family, the paper's HEBI modules.
    const auto defaults = names({});
    CHECK(defaults.size() == 6);
    CHECK(defaults.front() == "X5-1");
    try {
        allowed_actuators(std::vector<std::string>{"X5-1", "dynamixel"}, c);
        FAIL("an unknown name was allowed");
    } catch (const modsynth::task::InputError& e) {
        const std::string what = e.what();
        CHECK(what.find("robot.modules[1]: the module catalog has no \"dynamixel\"; its "
                        "families are dynamixel-x, feetech, hebi-x") == 0);
        CHECK(what.find("XL330-M288") != std::string::npos);
    }
}

TEST_CASE("the choice runs across families and totals the cost", "[hardware]") {
    const Catalog c = shipped();
    modsynth::task::Task task;
    auto robot = arm();
    robot.link_lengths = {0.20, 0.15};
    // A light, slow swing: an 18 g XL330 carries what the lightest HEBI
    // module (315 g) would.
    task.robot.modules = {"hebi-x", "dynamixel-x"};
    const auto sel = select_modules(task, robot, swing(0.3), c);
    REQUIRE(sel.carried());
    CHECK(sel.joints[1].module == "XL330-M288");
    CHECK(sel.joints[1].family == "dynamixel-x");
    REQUIRE(sel.joints[1].cost);
    CHECK(*sel.joints[1].cost == Approx(23.90));
    for (const auto& j : sel.joints) CHECK(j.family == "dynamixel-x");
    REQUIRE(sel.total_cost);
    CHECK(*sel.total_cost == Approx(*sel.joints[0].cost + *sel.joints[1].cost));
    CHECK(sel.message.find("(dynamixel-x; ") != std::string::npos);
    CHECK(sel.message.find("; cost: ") != std::string::npos);
    CHECK(sel.cost.find("cost: ") == 0);
    CHECK(sel.cost.find("XL330-M288 = $") != std::string::npos);
    // Modules without a price are said to be so, and leave no total.
    task.robot.modules = {"X5-1"};
    const auto hebi = select_modules(task, robot, swing(0.3), c);
    CHECK(hebi.cost == "cost: 2 x X5-1: cost unknown; total cost unknown");
    CHECK_FALSE(hebi.total_cost);
}

TEST_CASE("the cost line groups the models and totals them", "[hardware]") {
    const Catalog c = shipped();
    const Actuator* xm = c.actuator("XM430-W350");
    const Actuator* x5 = c.actuator("X5-1");
    // choose_modules with loads every module carries: each joint gets the
    // lightest allowed, so name one model per call.
    const auto zero = [](const std::vector<const Actuator*>& m) {
        return std::vector<JointLoad>(m.size());
    };
    const auto two = choose_modules(2, {xm}, zero);
    CHECK(two.cost == "cost: 2 x XM430-W350 = $579.80; total $579.80");
    REQUIRE(two.total_cost);
    CHECK(*two.total_cost == Approx(579.80));
    // Joint 1 needs 1 N m, more than an XL330 gives: an X5-1 it is, at no
    // known cost; joint 2 needs nothing.
    const Actuator* xl = c.actuator("XL330-M288");
    const auto mixed = choose_modules(2, {xl, x5}, [](const std::vector<const Actuator*>& m) {
        std::vector<JointLoad> loads(m.size());
        loads[0].peak_torque = loads[0].rms_torque = 1.0;
        return loads;
    });
    REQUIRE(mixed.carried());
    CHECK(mixed.cost ==
          "cost: 1 x X5-1: cost unknown, 1 x XL330-M288 = $23.90; total $23.90 plus the modules "
          "of unknown cost");
    CHECK_FALSE(mixed.total_cost);
    CHECK(mixed.message.find("modules X5-1, XL330-M288 (hebi-x, dynamixel-x; ") == 0);
}
