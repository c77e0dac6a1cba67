#pragma once
// OpenSCAD sources of the printed parts: each opens with its parameters, in
// mm, so that a person can edit them and render again. The link lies with
// its horn end plate on the bed: the horn axis is the z axis, the next axis
// is at x = link_length.
#include <string>

#include <modsynth/parts/link_design.h>

namespace modsynth::parts {

/// `title` opens the file as a comment (the task, the link).
std::string link_scad(const LinkDesign& link, const std::string& title);

/// The plate module 1 stands on, bolted to the table at its corners; the
/// origin is module 1's axis, the robot's base.
std::string base_plate_scad(const ModuleMount& first, double plate, const std::string& title);

/// The collar that holds the end-effector rod under the last link's far
/// end, bolted to it with two M3 screws either side of the rod.
std::string tool_holder_scad(double rod_diameter, double plate, const std::string& title);

/// Centre of the tool holder's screws from the rod's axis (m), across the
/// link: the last link's far end has holes there too.
double tool_screw_offset(double rod_diameter);

}  // namespace modsynth::parts
