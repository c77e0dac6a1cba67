#include <modsynth/parts/link_design.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace modsynth::parts {

namespace {

/// A diameter that differs by at least 1 mm from every screw hole of an
/// end, so that the checks tell the axis hole from the screws' holes.
double distinct_from(double wanted, double hole) {
    return std::abs(wanted - hole) < 0.001 ? hole + 0.002 : wanted;
}

}  // namespace

BeamSection beam_section(double peak_torque, const Mounting& horn, const PrintSettings& settings) {
    if (!(peak_torque >= 0.0))
        throw std::invalid_argument("beam_section: the peak torque must not be negative");
    BeamSection s;
    s.plate = std::max(0.004, 2.0 * horn.horn_hole_diameter);
    const double sigma = settings.allowable_stress();
    // Flange about the joint axis: W = t b^2 / 6; rib about the cross
    // axis: W = t h^2 / 6; both >= M / sigma.
    const double needed = std::sqrt(6.0 * peak_torque / (s.plate * sigma));
    s.flange_width = std::max({0.010, horn.horn_diameter, needed});
    s.rib_thickness = s.plate;
    s.rib_height = std::max(s.plate, needed);
    return s;
}

LinkDesign link_design(int index, double length, const ModuleMount& horn,
                       const std::optional<ModuleMount>& body, double rod_diameter,
                       double peak_torque, const PrintSettings& settings) {
    if (!(length > 0.0))
        throw std::invalid_argument("link_design: the link length must be positive");
    LinkDesign d;
    d.index = index;
    d.length = length;
    d.horn = horn;
    d.body = body;
    d.rod_diameter = rod_diameter;
    d.peak_torque = peak_torque;
    d.beam = beam_section(peak_torque, horn.mounting, settings);
    const Mounting& h = horn.mounting;
    d.horn_bore = distinct_from(std::max(h.horn_hole_diameter + 0.002, 0.4 * h.horn_diameter),
                                h.horn_hole_diameter);
    if (body) {
        const double hole = body->mounting.body_hole_diameter;
        d.axis_hole = distinct_from(std::max(0.004, hole + 0.002), hole);
    } else {
        // The rod's hole, 0.3 mm over the rod so that it slides in.
        d.axis_hole = distinct_from(rod_diameter + 0.0003, 0.0034);
    }
    return d;
}

}  // namespace modsynth::parts
