#pragma once
// How an actuator is fastened to the parts beside it: the bolt pattern of
// its output horn and the holes of its body, as catalog/*.json gives them
// (formats.md, "Module catalog"). Printed links are drawn from it.
#include <array>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace modsynth::hardware {

/// Lengths in m. The body frame has its origin on the output axis, x along
/// the body's length (away from the end nearest the axis), y across it.
struct Mounting {
    double horn_bolt_circle = 0.0;    ///< diameter of the circle the horn's holes sit on
    int horn_holes = 0;               ///< holes on that circle, evenly spaced
    double horn_hole_diameter = 0.0;  ///< clearance for the horn's screws
    double horn_diameter = 0.0;       ///< outer diameter of the horn
    /// Holes on the face opposite the horn, (x, y) in the body frame.
    std::vector<std::array<double, 2>> body_holes;
    double body_hole_diameter = 0.0;
    double output_offset = 0.0;  ///< the output axis from the body's nearer end, along its length
};

/// Reads the "mounting" object of an actuator entry whose body is
/// `body_length` long and `body_width` wide. `place` names the entry in
/// errors ("file.json: entries[2] (XM430-W350)"); throws CatalogError naming
/// the key ("...: mounting.horn_holes: ...") when a figure is missing, not
/// finite, not positive, or does not fit (holes outside the horn or off the
/// body, the axis outside the body).
Mounting parse_mounting(const nlohmann::json& value, const std::string& place, double body_length,
                        double body_width);

}  // namespace modsynth::hardware
