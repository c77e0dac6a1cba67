#include <catch2/catch.hpp>

#include <regex>
#include <string>

#include <modsynth/parts/link_design.h>
#include <modsynth/parts/scad_writer.h>

using namespace modsynth::parts;

namespace {

ModuleMount x5() {
    modsynth::hardware::Actuator a;
    a.name = "X5-9";
    a.peak_torque = 13.0;
    a.dimensions = {0.110, 0.073, 0.031};
    return module_mount(a, {});
}

/// The value a parameter line `name = value;` sets.
double parameter(const std::string& scad, const std::string& name) {
    std::smatch m;
    const std::regex re("\n" + name + R"( = ([-0-9.]+);)");
    REQUIRE(std::regex_search(scad, m, re));
    return std::stod(m[1]);
}

}  // namespace

TEST_CASE("a link's source opens with its parameters, in mm", "[parts]") {
    const PrintSettings settings;
    const LinkDesign l = link_design(2, 0.1524, x5(), x5(), 0.0095, 13.0, settings);
    const std::string scad = link_scad(l, "rose: link 2 of 3");
    CHECK(scad.rfind("// rose: link 2 of 3\n", 0) == 0);
    CHECK(parameter(scad, "link_length") == Approx(152.4));
    CHECK(parameter(scad, "plate") == Approx(l.beam.plate * 1000.0).margin(1e-3));
    CHECK(parameter(scad, "flange_width") == Approx(l.beam.flange_width * 1000.0).margin(1e-3));
    CHECK(parameter(scad, "horn_holes") == 4);
    CHECK(parameter(scad, "horn_bore") == Approx(l.horn_bore * 1000.0).margin(1e-3));
    CHECK(parameter(scad, "axis_hole") == Approx(l.axis_hole * 1000.0).margin(1e-3));
    CHECK(parameter(scad, "body_output_offset") == Approx(18.5));
    // Every parameter comes before the geometry, so that a person finds
    // them at the top.
    CHECK(scad.find("link_length =") < scad.find("difference()"));
    CHECK(scad.find("body_holes = [[") < scad.find("module far_end"));
    // The next axis's hole is drawn at link_length, the horn's at the origin.
    CHECK(scad.find("translate([link_length, 0, -1]) cylinder(d = axis_hole") != std::string::npos);
    CHECK(scad.find("cylinder(d = horn_bore") != std::string::npos);
    // The generic bolt pattern is said.
    CHECK(scad.find("generic") != std::string::npos);
}

TEST_CASE("the last link carries the tool holder's holes", "[parts]") {
    const PrintSettings settings;
    const LinkDesign l = link_design(3, 0.2, x5(), std::nullopt, 0.0095, 13.0, settings);
    const std::string scad = link_scad(l, "last");
    CHECK(parameter(scad, "axis_hole") == Approx(9.8));
    CHECK(parameter(scad, "tool_screw_offset") == Approx(tool_screw_offset(0.0095) * 1000.0));
    CHECK(scad.find("body_holes") == std::string::npos);
    const std::string holder = tool_holder_scad(0.0095, l.beam.plate, "holder");
    // Its screws meet the link's.
    CHECK(parameter(holder, "screw_offset") == Approx(parameter(scad, "tool_screw_offset")));
    CHECK(parameter(holder, "rod_diameter") == Approx(9.5));
}

TEST_CASE("the base plate carries module 1's body pattern round the base", "[parts]") {
    const std::string scad = base_plate_scad(x5(), 0.0064, "base");
    CHECK(parameter(scad, "plate") == Approx(6.4));
    CHECK(parameter(scad, "body_length") == Approx(110.0));
    CHECK(scad.find("body_centre = -body_output_offset;") != std::string::npos);
}
