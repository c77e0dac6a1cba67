#pragma once
// The filament, and how a part is printed: what the build sheet tells the
// person at the printer, what sizes the beams and what turns a mesh's
// volume into the mass the arm's dynamics carry.
#include <string>

namespace modsynth::parts {

struct Material {
    std::string name;       ///< "PLA"
    double density = 0.0;   ///< kg/m^3 of the solid filament
    double strength = 0.0;  ///< Pa, tensile strength of a part printed flat, along its layers
};

/// PLA: 1240 kg/m^3, 40 MPa along the layers of a flat print (below the
/// filament's 50-60 MPa: the bonds between roads are weaker).
Material pla();
/// PETG: 1270 kg/m^3, 30 MPa.
Material petg();

struct PrintSettings {
    Material material = pla();
    double infill = 0.4;  ///< fraction, gyroid
    int perimeters = 4;
    double layer_height = 0.0002;  ///< m
    /// The beams' sizing: allowable stress = material.strength / safety_factor.
    double safety_factor = 3.0;
    /// Mass per volume of the printed part over the solid filament's: the
    /// walls and the top and bottom layers of a 6 mm plate are solid and
    /// take about half of it, the rest is infill (0.4), so 0.7 with the
    /// ribs' solid walls: an estimate on the heavy side, which overstates
    /// the torques rather than understating them.
    double solid_fraction = 0.7;

    double allowable_stress() const { return material.strength / safety_factor; }
    /// kg/m^3 of the printed part.
    double printed_density() const { return material.density * solid_fraction; }
};

}  // namespace modsynth::parts
