#pragma once
// A printable link, as numbers: the module whose output (horn) it is
// bolted to at one end, the module whose body it carries (or the tool) at
// the other, link_length apart, and the beam between. What scad_writer.h
// writes and what the checks (hole_spacing.h) measure the mesh against.
#include <optional>
#include <string>

#include <modsynth/parts/mounting.h>
#include <modsynth/parts/print_settings.h>

namespace modsynth::parts {

/// The section of the beam between the ends: a flat flange on the bed,
/// with a rib standing on its centre line. Lengths in m.
struct BeamSection {
    double plate = 0.0;  ///< thickness of the flange and of the end plates
    double flange_width = 0.0;
    double rib_thickness = 0.0;
    double rib_height = 0.0;  ///< above the flange
};

/// The rule: the beam carries the driving module's peak torque M (the most
/// it can put into the link, at a stall or a collision) as a bending moment
/// at its root, about either axis. About the joint axis the flange alone
/// carries it, b^2 t / 6 >= M / sigma; about the axis across the link the
/// rib alone, t h^2 / 6 >= M / sigma; sigma is the settings' allowable
/// stress. The plate is twice the horn's screw hole (at least 4 mm) thick;
/// the flange is at least 10 mm wide and as wide as the horn; the rib as
/// thick as the plate. Throws std::invalid_argument for a negative torque.
BeamSection beam_section(double peak_torque, const Mounting& horn, const PrintSettings& settings);

struct LinkDesign {
    int index = 1;        ///< 1-based: link k joins joint k to joint k + 1 (or the tool)
    double length = 0.0;  ///< m, horn axis to the next axis (or the tool's)
    ModuleMount horn;     ///< module k, its output under the link's first end
    /// Module k + 1, its body on the link's far end; none on the last link,
    /// whose far end carries the tool holder.
    std::optional<ModuleMount> body;
    double rod_diameter = 0.0;  ///< m, the end-effector rod's (last link)
    double peak_torque = 0.0;   ///< N m, module k's
    BeamSection beam;
    /// Diameters (m) of the two holes whose centres are the link's axes:
    /// the bore under the horn's hub and a locating hole on the next axis
    /// (the rod's hole on the last link). Each differs from every screw
    /// hole of its end, so that the checks find them in the mesh.
    double horn_bore = 0.0;
    double axis_hole = 0.0;
};

/// The link from its ends and length, sized by beam_section. Throws
/// std::invalid_argument when the length is not positive.
LinkDesign link_design(int index, double length, const ModuleMount& horn,
                       const std::optional<ModuleMount>& body, double rod_diameter,
                       double peak_torque, const PrintSettings& settings);

}  // namespace modsynth::parts
