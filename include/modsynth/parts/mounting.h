#pragma once
// How a module is bolted to a printed part: the bolt pattern of its output
// (the horn) and of its body. The fields mirror the catalog's optional
// "mounting" key (formats.md, "Module catalog") in the printed parts' frame;
// for an actuator without one, provisional_mounting derives a generic
// pattern from its dimensions.
#include <string>
#include <vector>

#include <modsynth/geometry/vec.h>
#include <modsynth/hardware/catalog.h>

namespace modsynth::parts {

/// Lengths in m. Body holes are in the body's mounting face, from the
/// centre of its footprint, x along its length towards the output end; the
/// output axis is at (output_offset, 0).
struct Mounting {
    double horn_bolt_circle = 0.0;  ///< diameter
    int horn_holes = 0;
    double horn_hole_diameter = 0.0;
    double horn_diameter = 0.0;
    std::vector<geometry::Vec2> body_holes;
    double body_hole_diameter = 0.0;
    double output_offset = 0.0;
};

/// A module as the printed parts see it: its housing and its bolt pattern.
struct ModuleMount {
    std::string name;           ///< the actuator's, as the build sheet names it
    hardware::Dimensions body;  ///< m: length along the link, width across, height on the axis
    Mounting mounting;
    bool provisional = true;  ///< the pattern is provisional_mounting's, not the maker's
};

/// The generic pattern of a housing of these dimensions (m), for a module
/// whose maker's pattern the catalog does not give: the output axis
/// width / 2 from the output end (as hardware/stack.h places it), a horn of
/// half the width with 4 holes on a circle of 0.7 of its diameter, and 4
/// body holes inset by a tenth of the width (at least 4 mm) from the
/// footprint's corners; M3 clearance holes (3.2 mm), M2 (2.2 mm) on a
/// housing narrower than 30 mm. Throws std::invalid_argument when a
/// dimension is not positive.
Mounting provisional_mounting(const hardware::Dimensions& body);

/// The module of `actuator`, its housing from its dimensions, or from
/// `fallback` (the task's module size) where the catalog gives none; its
/// pattern the catalog's "mounting" when the entry has one (provisional
/// false), else provisional_mounting's.
ModuleMount module_mount(const hardware::Actuator& actuator, const hardware::Dimensions& fallback);

}  // namespace modsynth::parts
