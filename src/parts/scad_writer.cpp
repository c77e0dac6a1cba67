#include <modsynth/parts/scad_writer.h>

#include <modsynth/text/format.h>
#include <modsynth/text/scad.h>

namespace modsynth::parts {

namespace {

using text::format;
// Every name written below is a comment's text: a line break in a task's or
// a module's name must not turn the rest of it into code.
using text::scad_comment;

constexpr double kMm = 1000.0;
/// Wall round the horn and round the rod, mm.
constexpr double kRim = 4.0;
/// M3 clearance: the tool holder's screws.
constexpr double kToolScrewHole = 3.4;

/// "[[x, y], ...]" in mm.
std::string points_mm(const std::vector<geometry::Vec2>& points) {
    std::string out = "[";
    for (std::size_t i = 0; i < points.size(); ++i)
        out += format("%s[%.3f, %.3f]", i ? ", " : "", points[i].x() * kMm, points[i].y() * kMm);
    return out + "]";
}

std::string body_parameters(const ModuleMount& m) {
    return format(
        "body_length = %.3f;         // %s's housing, along the link\n"
        "body_width = %.3f;\n"
        "body_output_offset = %.3f;   // housing centre to its output axis, along its length\n"
        "body_holes = %s;  // from the housing centre, x towards its output\n"
        "body_hole = %.3f;\n",
        m.body.length * kMm, scad_comment(m.name).c_str(), m.body.width * kMm,
        m.mounting.output_offset * kMm, points_mm(m.mounting.body_holes).c_str(),
        m.mounting.body_hole_diameter * kMm);
}

std::string provenance(const ModuleMount& m) {
    return m.provisional
               ? format(
                     "// %s's bolt pattern is the generic one for its housing (the catalog "
                     "gives none):\n// check it against the module before printing.\n",
                     scad_comment(m.name).c_str())
               : std::string();
}

}  // namespace

double tool_screw_offset(double rod_diameter) {
    return (rod_diameter * kMm / 2.0 + kRim + kToolScrewHole) / kMm;
}

std::string link_scad(const LinkDesign& link, const std::string& title) {
    const Mounting& h = link.horn.mounting;
    std::string s = format("// %s\n", scad_comment(title).c_str());
    s += format(
        "// Printed link %d: %s's output (its horn) is bolted under the end at the\n"
        "// origin; %s, at link_length along +x.\n"
        "// Units: mm. Print it flat, the end plates on the bed, without supports.\n"
        "// Edit the parameters; the two axes stay link_length apart.\n",
        link.index, scad_comment(link.horn.name).c_str(),
        link.body ? (scad_comment(link.body->name) + "'s housing stands on the far end").c_str()
                  : "the tool holder hangs from the far end");
    s += provenance(link.horn);
    if (link.body && link.body->name != link.horn.name) s += provenance(*link.body);
    s += format(
        "\n"
        "link_length = %.4f;   // horn axis to the next axis\n"
        "plate = %.3f;          // end plates and flange\n"
        "flange_width = %.3f;   // sized for %s's peak torque, %.2f N m\n"
        "rib_thickness = %.3f;\n"
        "rib_height = %.3f;     // above the flange\n"
        "rim = %.1f;             // wall round the horn\n"
        "\n"
        "horn_diameter = %.3f;\n"
        "horn_bolt_circle = %.3f;  // diameter\n"
        "horn_holes = %d;\n"
        "horn_hole = %.3f;\n"
        "horn_bore = %.3f;      // over the horn's hub; its centre is the horn axis\n",
        link.length * kMm, link.beam.plate * kMm, link.beam.flange_width * kMm,
        scad_comment(link.horn.name).c_str(), link.peak_torque, link.beam.rib_thickness * kMm,
        link.beam.rib_height * kMm, kRim, h.horn_diameter * kMm, h.horn_bolt_circle * kMm,
        h.horn_holes, h.horn_hole_diameter * kMm, link.horn_bore * kMm);
    if (link.body) {
        s += "\n" + body_parameters(*link.body);
        s += format("axis_hole = %.3f;      // locating hole on the next axis\n",
                    link.axis_hole * kMm);
    } else {
        s += format(
            "\n"
            "axis_hole = %.3f;      // the end-effector rod's hole, on the tool's axis\n"
            "tool_screw_offset = %.3f;  // the tool holder's two screws, either side of the rod\n"
            "tool_screw_hole = %.1f;\n",
            link.axis_hole * kMm, tool_screw_offset(link.rod_diameter) * kMm, kToolScrewHole);
    }
    s += "\n$fn = 96;\n\nhorn_outer = horn_diameter + 2 * rim;\n";
    if (link.body) {
        s += R"(body_centre = link_length - body_output_offset;
pad_start = body_centre - body_length / 2;

module far_end() {
    translate([pad_start, -body_width / 2, 0]) cube([body_length, body_width, plate]);
}
module far_holes() {
    for (p = body_holes)
        translate([body_centre + p[0], p[1], -1]) cylinder(d = body_hole, h = plate + 2, $fn = 24);
    translate([link_length, 0, -1]) cylinder(d = axis_hole, h = plate + 2);
}
)";
    } else {
        s += R"(tool_pad_length = axis_hole + 4 * rim;
tool_pad_width = 2 * (tool_screw_offset + tool_screw_hole / 2 + rim);
pad_start = link_length - tool_pad_length / 2;

module far_end() {
    translate([pad_start, -tool_pad_width / 2, 0]) cube([tool_pad_length, tool_pad_width, plate]);
}
module far_holes() {
    translate([link_length, 0, -1]) cylinder(d = axis_hole, h = plate + 2);
    for (s = [-1, 1])
        translate([link_length, s * tool_screw_offset, -1])
            cylinder(d = tool_screw_hole, h = plate + 2, $fn = 24);
}
)";
    }
    s += R"(
difference() {
    union() {
        cylinder(d = horn_outer, h = plate);
        far_end();
        translate([0, -flange_width / 2, 0]) cube([max(pad_start, 0.01), flange_width, plate]);
        if (pad_start > horn_outer / 2 + 1)
            translate([horn_outer / 2, -rib_thickness / 2, plate - 0.01])
                cube([pad_start - horn_outer / 2, rib_thickness, rib_height + 0.01]);
    }
    translate([0, 0, -1]) cylinder(d = horn_bore, h = plate + 2);
    for (i = [0 : horn_holes - 1])
        rotate(45 + i * 360 / horn_holes)
            translate([horn_bolt_circle / 2, 0, -1]) cylinder(d = horn_hole, h = plate + 2, $fn = 24);
    far_holes();
}
)";
    return s;
}

std::string base_plate_scad(const ModuleMount& first, double plate, const std::string& title) {
    std::string s = format("// %s\n", scad_comment(title).c_str());
    s += "// The base plate: module 1's housing stands on it, and it is bolted to the\n"
         "// table at its corners (M5). The origin is module 1's axis, the robot's\n"
         "// base. Units: mm. Print it flat, without supports.\n";
    s += provenance(first);
    s += format(
        "\nplate = %.3f;\nmargin = 25.0;         // round the housing, for the table's bolts\n"
        "table_hole = 5.5;\n",
        plate * kMm);
    s += body_parameters(first);
    s += R"(
body_centre = -body_output_offset;

difference() {
    translate([body_centre - body_length / 2 - margin, -body_width / 2 - margin, 0])
        cube([body_length + 2 * margin, body_width + 2 * margin, plate]);
    for (p = body_holes)
        translate([body_centre + p[0], p[1], -1]) cylinder(d = body_hole, h = plate + 2, $fn = 24);
    for (sx = [-1, 1], sy = [-1, 1])
        translate([body_centre + sx * (body_length / 2 + margin / 2), sy * (body_width / 2 + margin / 2), -1])
            cylinder(d = table_hole, h = plate + 2, $fn = 24);
}
)";
    return s;
}

std::string tool_holder_scad(double rod_diameter, double plate, const std::string& title) {
    std::string s = format("// %s\n", scad_comment(title).c_str());
    s += "// The tool holder: a collar round the end-effector rod, bolted under the\n"
         "// last link's far end with two M3 screws; an M3 set screw clamps the rod.\n"
         "// Units: mm. Print it on its flange, the collar up, without supports.\n";
    s += format(
        "\nrod_diameter = %.3f;\nrod_hole = rod_diameter + 0.3;\nplate = %.3f;\n"
        "wall = %.1f;\ncollar_height = 25.0;\nscrew_offset = %.3f;  // matches the last link\n"
        "screw_hole = %.1f;\nset_screw_hole = 2.5;   // tapped M3\n\n$fn = 96;\n",
        rod_diameter * kMm, plate * kMm, kRim, tool_screw_offset(rod_diameter) * kMm,
        kToolScrewHole);
    s += R"(
flange_width = 2 * (screw_offset + screw_hole / 2 + wall);
flange_length = rod_hole + 2 * wall;

difference() {
    union() {
        translate([-flange_length / 2, -flange_width / 2, 0]) cube([flange_length, flange_width, plate]);
        cylinder(d = rod_hole + 2 * wall, h = collar_height);
    }
    translate([0, 0, -1]) cylinder(d = rod_hole, h = collar_height + 2);
    for (s = [-1, 1])
        translate([0, s * screw_offset, -1]) cylinder(d = screw_hole, h = plate + 2, $fn = 24);
    translate([0, 0, (plate + collar_height) / 2]) rotate([0, 90, 0])
        cylinder(d = set_screw_hole, h = rod_hole + 2 * wall, $fn = 24);
}
)";
    return s;
}

}  // namespace modsynth::parts
