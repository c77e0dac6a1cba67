#pragma once
// The check that a printed link puts its two axes where the robot has them:
// the link's mesh is cut through its end plates, the horn's bore and the
// next axis's hole are found among the loops of the section by their
// diameters, and the distance between their centres is measured.
#include <optional>
#include <string>
#include <vector>

#include <modsynth/geometry/vec.h>
#include <modsynth/parts/link_design.h>
#include <modsynth/parts/stl_mesh.h>

namespace modsynth::parts {

/// A loop of a section: its centre (the centroid of the polygon, which is
/// the centre of a regular polygon) and the diameter of the circle of the
/// same area.
struct SectionLoop {
    geometry::Vec2 centre = geometry::Vec2::Zero();
    double diameter = 0.0;
};

std::vector<SectionLoop> section_loops(const Mesh& mesh, double z);

struct SpacingCheck {
    bool ok = false;
    double measured = 0.0;  ///< m
    double expected = 0.0;  ///< m, the link length
    std::string message;    ///< what was measured, or why it could not be
};

/// Within this of the link length (m).
inline constexpr double kSpacingTolerance = 1e-4;

/// `mesh` in mm, as OpenSCAD writes the link's source (scad_writer.h).
SpacingCheck check_spacing(const Mesh& mesh, const LinkDesign& link);

}  // namespace modsynth::parts
