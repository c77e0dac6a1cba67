#include <modsynth/parts/mounting.h>

#include <algorithm>
#include <stdexcept>

namespace modsynth::parts {

Mounting provisional_mounting(const hardware::Dimensions& body) {
    if (!(body.length > 0.0) || !(body.width > 0.0) || !(body.height > 0.0))
        throw std::invalid_argument(
            "provisional_mounting: the housing's dimensions must be positive");
    const double L = body.length, W = body.width;
    const double clearance = W < 0.030 ? 0.0022 : 0.0032;
    Mounting m;
    m.horn_diameter = 0.5 * W;
    m.horn_bolt_circle = 0.7 * m.horn_diameter;
    m.horn_holes = 4;
    m.horn_hole_diameter = clearance;
    m.body_hole_diameter = clearance;
    const double inset = std::max(0.004, 0.1 * W);
    for (double sx : {-1.0, 1.0})
        for (double sy : {-1.0, 1.0})
            m.body_holes.emplace_back(sx * (L / 2.0 - inset), sy * (W / 2.0 - inset));
    m.output_offset = L / 2.0 - W / 2.0;
    return m;
}

ModuleMount module_mount(const hardware::Actuator& actuator, const hardware::Dimensions& fallback) {
    ModuleMount out;
    out.name = actuator.name;
    const hardware::Dimensions& d = actuator.dimensions;
    out.body = d.length > 0.0 && d.width > 0.0 && d.height > 0.0 ? d : fallback;
    if (!actuator.mounting) {
        out.mounting = provisional_mounting(out.body);
        out.provisional = true;
        return out;
    }
    // The catalog measures from the output axis, x away from the housing's
    // nearer end; the printed parts from the housing's centre, x towards
    // that end.
    const hardware::Mounting& c = *actuator.mounting;
    Mounting& m = out.mounting;
    m.horn_bolt_circle = c.horn_bolt_circle;
    m.horn_holes = c.horn_holes;
    m.horn_hole_diameter = c.horn_hole_diameter;
    m.horn_diameter = c.horn_diameter;
    m.body_hole_diameter = c.body_hole_diameter;
    m.output_offset = out.body.length / 2.0 - c.output_offset;
    for (const auto& [x, y] : c.body_holes) m.body_holes.emplace_back(m.output_offset - x, y);
    out.provisional = false;
    return out;
}

}  // namespace modsynth::parts
