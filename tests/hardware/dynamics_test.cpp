#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include <modsynth/hardware/arm_model.h>
#include <modsynth/hardware/catalog.h>
#include <modsynth/hardware/dynamics.h>
#include <modsynth/hardware/stack.h>

using namespace modsynth::hardware;
using modsynth::geometry::Vec2;

TEST_CASE("a link's parts combine by the parallel-axis theorem", "[hardware]") {
    LinkBody b;
    add_part(b, 1.0, 0.0);
    add_part(b, 1.0, 1.0);
    CHECK(b.mass == 2.0);
    CHECK(b.com == 0.5);
    CHECK(b.inertia == Approx(0.5));  // two unit masses 0.5 m either side
    add_part(b, 0.0, 5.0);            // nothing
    CHECK(b.com == 0.5);
}

TEST_CASE("inverse dynamics: statics in an upright plane, inertia in a level one", "[hardware]") {
    ArmModel m;
    m.link_lengths = {0.5, 0.4};
    m.links = {{2.0, 0.25, 0.01}, {1.0, 0.4, 0.0}};
    const double g = 9.81;
    m.gravity = Vec2(0.0, -g);
    // Stretched out along x at rest: each joint holds the weight beyond it.
    auto tau = inverse_dynamics(m, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0});
    CHECK(tau[1] == Approx(1.0 * g * 0.4));
    CHECK(tau[0] == Approx(2.0 * g * 0.25 + 1.0 * g * 0.9));
    // Pointing straight up: no moment.
    tau = inverse_dynamics(m, {M_PI / 2, 0.0}, {0.0, 0.0}, {0.0, 0.0});
    CHECK(tau[0] == Approx(0.0).margin(1e-12));
    // Level plane, spinning joint 1 alone at constant speed: the distal
    // point mass pulls outwards along link 2, which only loads joint 1 by
    // the centripetal force's arm, zero when the arm is straight.
    m.gravity = Vec2::Zero();
    tau = inverse_dynamics(m, {0.3, 0.0}, {2.0, 0.0}, {0.0, 0.0});
    CHECK(tau[0] == Approx(0.0).margin(1e-12));
    CHECK(tau[1] == Approx(0.0).margin(1e-12));
    // Accelerating joint 1 with the arm straight: the moment of inertia
    // about the base times the acceleration.
    tau = inverse_dynamics(m, {0.3, 0.0}, {0.0, 0.0}, {3.0, 0.0});
    const double inertia = 0.01 + 2.0 * 0.25 * 0.25 + 1.0 * 0.9 * 0.9;
    CHECK(tau[0] == Approx(inertia * 3.0));
    CHECK(tau[1] == Approx(1.0 * 0.9 * 0.4 * 3.0));
    CHECK_THROWS_AS(inverse_dynamics(m, {0.0}, {0.0, 0.0}, {0.0, 0.0}), std::invalid_argument);
}

TEST_CASE("the arm model counts every part of the catalog once", "[hardware]") {
    const Catalog c = load_catalog(std::string(MODSYNTH_SOURCE_DIR) + "/catalog");
    modsynth::task::RobotSpec spec;
    spec.payload = 0.25;
    modsynth::kinematics::Robot robot;
    robot.link_lengths = {0.35, 0.30};
    robot.link_diameter = spec.link_diameter;
    const Actuator* x8 = c.actuator("X8-9");
    const Actuator* x5 = c.actuator("X5-4");
    const ArmModel m = arm_model(spec, robot, c, {x8, x5});
    const auto cuts = tube_cuts(spec, robot);
    const double tube = c.tube_closest_to(spec.link_diameter).mass_per_metre;
    const double rod = c.tube_closest_to(spec.ee_rod_diameter).mass_per_metre *
                       ee_rod_length(spec, robot.link_diameter, 2);
    const double adapter = c.adapter().mass;
    // Link 1: its tube, two adapters and module 2 (the X5-4, not joint 1's).
    CHECK(m.links[0].mass == Approx(tube * cuts[0].cut_length + 2 * adapter + x5->mass));
    // Link 2: its tube, one adapter, the rod and the payload.
    CHECK(m.links[1].mass == Approx(tube * cuts[1].cut_length + adapter + rod + 0.25));
    CHECK(m.links[1].com > 0.5 * robot.link_lengths[1]);  // the tool end is heavy
    CHECK(m.gravity == Vec2::Zero());                     // along the axes by default
}

TEST_CASE("printed links take the place of the tubes and their adapters", "[hardware][parts]") {
    const Catalog c = load_catalog(std::string(MODSYNTH_SOURCE_DIR) + "/catalog");
    modsynth::task::RobotSpec spec;
    modsynth::kinematics::Robot robot;
    robot.link_lengths = {0.35, 0.30};
    robot.link_diameter = spec.link_diameter;
    const std::vector<const Actuator*> modules = {c.actuator("X5-9"), c.actuator("X5-4")};
    const ArmModel tubes = arm_model(spec, robot, c, modules);
    const std::vector<PrintedLink> printed = {{0.12, 0.16, 0.002}, {0.08, 0.14, 0.001}};
    const ArmModel model = arm_model(spec, robot, c, modules, printed);
    // Link 1: the printed link and module 2's housing, no tube or adapter.
    const double L = spec.module_length, W = spec.module_width;
    LinkBody expected;
    add_part(expected, 0.12, 0.16, 0.002);
    add_part(expected, modules[1]->mass, 0.35 - (L / 2 - W / 2),
             modules[1]->mass * (L * L + W * W) / 12.0);
    CHECK(model.links[0].mass == Approx(expected.mass));
    CHECK(model.links[0].com == Approx(expected.com));
    CHECK(model.links[0].inertia == Approx(expected.inertia));
    CHECK(model.links[0].mass < tubes.links[0].mass);
    // The last link keeps the rod and the payload at the tool.
    const Tube& rod = c.tube_closest_to(spec.ee_rod_diameter);
    CHECK(model.links[1].mass ==
          Approx(0.08 + rod.mass_per_metre * ee_rod_length(spec, robot.link_diameter, 2)));
    CHECK_THROWS_AS(arm_model(spec, robot, c, modules, {printed[0]}), std::invalid_argument);
}
