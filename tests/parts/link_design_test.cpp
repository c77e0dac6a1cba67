#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include <modsynth/parts/link_design.h>
#include <modsynth/parts/mounting.h>
#include <modsynth/parts/screws.h>

using namespace modsynth::parts;
using modsynth::hardware::Actuator;
using modsynth::hardware::Dimensions;

namespace {

Actuator x5() {
    Actuator a;
    a.name = "X5-9";
    a.mass = 0.36;
    a.peak_torque = 13.0;
    a.dimensions = {0.110, 0.073, 0.031};
    return a;
}

}  // namespace

TEST_CASE("the provisional mounting follows the housing's size", "[parts]") {
    const Mounting m = provisional_mounting({0.110, 0.073, 0.031});
    CHECK(m.horn_diameter == Approx(0.0365));
    CHECK(m.horn_bolt_circle == Approx(0.7 * 0.0365));
    CHECK(m.horn_holes == 4);
    CHECK(m.horn_hole_diameter == 0.0032);
    // The axis width / 2 from the output end, as the stack places it.
    CHECK(m.output_offset == Approx(0.110 / 2 - 0.073 / 2));
    REQUIRE(m.body_holes.size() == 4);
    for (const auto& h : m.body_holes) {
        CHECK(std::abs(h.x()) == Approx(0.055 - 0.0073));
        CHECK(std::abs(h.y()) == Approx(0.0365 - 0.0073));
    }
    // A small servo's housing gets M2 holes, inset at least 4 mm.
    const Mounting s = provisional_mounting({0.034, 0.020, 0.026});
    CHECK(s.horn_hole_diameter == 0.0022);
    CHECK(std::abs(s.body_holes[0].y()) == Approx(0.010 - 0.004));
    CHECK_THROWS_AS(provisional_mounting({0.0, 0.02, 0.02}), std::invalid_argument);
}

TEST_CASE("a module without dimensions takes the task's housing", "[parts]") {
    Actuator a = x5();
    a.dimensions = {};
    const ModuleMount m = module_mount(a, {0.2, 0.1, 0.05});
    CHECK(m.name == "X5-9");
    CHECK(m.body.length == 0.2);
    CHECK(m.provisional);
    CHECK(module_mount(x5(), {0.2, 0.1, 0.05}).body.length == 0.110);
}

TEST_CASE("a catalog pattern is used in the printed parts' frame", "[parts]") {
    Actuator a = x5();
    modsynth::hardware::Mounting c;
    c.horn_bolt_circle = 0.016;
    c.horn_holes = 8;
    c.horn_hole_diameter = 0.0022;
    c.horn_diameter = 0.020;
    c.body_hole_diameter = 0.0025;
    c.output_offset = 0.0135;                      // axis 13.5 mm from the housing's nearer end
    c.body_holes = {{0.070, 0.02}, {0.0, -0.02}};  // from the axis, away from that end
    a.mounting = c;
    const ModuleMount m = module_mount(a, {});
    CHECK_FALSE(m.provisional);
    CHECK(m.mounting.horn_holes == 8);
    CHECK(m.mounting.horn_bolt_circle == 0.016);
    // From the housing's centre towards its nearer end: 55 - 13.5 mm.
    CHECK(m.mounting.output_offset == Approx(0.0415));
    REQUIRE(m.mounting.body_holes.size() == 2);
    CHECK(m.mounting.body_holes[0].x() == Approx(0.0415 - 0.070));
    CHECK(m.mounting.body_holes[0].y() == Approx(0.02));
    // A hole on the axis stays on it.
    CHECK(m.mounting.body_holes[1].x() == Approx(m.mounting.output_offset));
}

TEST_CASE("the beam carries the driving module's peak torque at the allowable stress", "[parts]") {
    const PrintSettings settings;
    CHECK(settings.allowable_stress() == Approx(40e6 / 3.0));
    const Mounting horn = provisional_mounting({0.110, 0.073, 0.031});
    // An X8-16's 38 N m needs more than the horn's width.
    const BeamSection s = beam_section(38.0, horn, settings);
    CHECK(s.plate == Approx(0.0064));
    CHECK(s.flange_width > horn.horn_diameter);
    // Section modulus t b^2 / 6 of the flange carries M at sigma.
    const double stress = 38.0 / (s.plate * s.flange_width * s.flange_width / 6.0);
    CHECK(stress == Approx(settings.allowable_stress()));
    CHECK(38.0 / (s.rib_thickness * s.rib_height * s.rib_height / 6.0) ==
          Approx(settings.allowable_stress()));
    // A weak module still gets a beam as wide as its horn.
    CHECK(beam_section(0.1, horn, settings).flange_width == Approx(horn.horn_diameter));
    // PETG is weaker: a wider flange for the same torque.
    PrintSettings petg_settings;
    petg_settings.material = petg();
    CHECK(beam_section(38.0, horn, petg_settings).flange_width > s.flange_width);
    CHECK_THROWS_AS(beam_section(-1.0, horn, settings), std::invalid_argument);
}

TEST_CASE("a link's axis holes differ from its screw holes", "[parts]") {
    const PrintSettings settings;
    const ModuleMount m = module_mount(x5(), {});
    const LinkDesign l = link_design(1, 0.2, m, m, 0.0095, 13.0, settings);
    CHECK(l.length == 0.2);
    CHECK(std::abs(l.horn_bore - m.mounting.horn_hole_diameter) >= 0.001);
    CHECK(std::abs(l.axis_hole - m.mounting.body_hole_diameter) >= 0.001);
    const LinkDesign last = link_design(2, 0.2, m, std::nullopt, 0.0095, 13.0, settings);
    CHECK(last.axis_hole == Approx(0.0098));
    CHECK_THROWS_AS(link_design(1, 0.0, m, m, 0.0095, 13.0, settings), std::invalid_argument);
}

TEST_CASE("screws are sized by their holes and cut to stock lengths", "[parts]") {
    CHECK(metric_size(0.0032) == "M3");
    CHECK(metric_size(0.0034) == "M3");
    CHECK(metric_size(0.0022) == "M2");
    CHECK(metric_size(0.0027) == "M2.5");
    CHECK(metric_size(0.0055) == "M5");
    CHECK(stock_length(0.0124) == Approx(0.014));
    CHECK(stock_length(0.012) == Approx(0.012));
    const Screw s = through_plate(0.0032, 0.0064, 4, "horn");
    CHECK(s.size == "M3");
    CHECK(s.length == Approx(0.014));  // 6.4 mm plate + 2 x 3 mm of thread
    CHECK(s.count == 4);

    const PrintSettings settings;
    const ModuleMount m = module_mount(x5(), {});
    const std::vector<LinkDesign> links = {
        link_design(1, 0.2, m, m, 0.0095, 13.0, settings),
        link_design(2, 0.2, m, std::nullopt, 0.0095, 13.0, settings)};
    int m3 = 0;
    for (const auto& sc : arm_screws(links, m, 0.0064))
        if (sc.size == "M3") m3 += sc.count;
    // Base 4, link 1 horn 4 and module 2 body 4, link 2 horn 4, tool
    // holder 2 and its set screw.
    CHECK(m3 == 4 + 4 + 4 + 4 + 2 + 1);
}
