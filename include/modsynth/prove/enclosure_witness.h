#pragma once
// The witness of a wall in space (formats.md "Spatial tasks",
// `explanation.enclosure`): a closed set of grid cells around one side, the
// base region or a point of the path, whose every neighbour outside it lies
// inside one obstacle grown by link_diameter / 2. A reader re-checks it with
// nothing but the task.
#include <array>
#include <vector>

#include <modsynth/geometry/vec3.h>

namespace modsynth::prove {

/// Cells of side `cell`: cell (i, j, k) is the closed box from
/// origin + (i, j, k) cell to origin + (i + 1, j + 1, k + 1) cell, for
/// 0 <= i < size[0] and so on. `cell` is a power of two and `origin` a
/// multiple of it, so that every corner is exact in binary.
struct EnclosureGrid {
    geometry::Vec3 origin = geometry::Vec3::Zero();
    double cell = 0.0;
    std::array<int, 3> size{0, 0, 0};
};

/// One run of cells along x: (i, j, k) for i from i0 to i1 (both included).
struct CellRun {
    int j = 0, k = 0, i0 = 0, i1 = 0;
};

/// A closed shell between base_regions[base_region] and `point` (on
/// trajectory[primitive]).
struct Enclosure {
    int base_region = 0;
    int primitive = 0;
    geometry::Vec3 point = geometry::Vec3::Zero();
    /// The obstacles of the shell, ascending.
    std::vector<int> obstacles;
    EnclosureGrid grid;
    /// Which side `cells` holds: the base region's (true) or the point's.
    bool base_inside = true;
    /// The enclosed cells: they hold every cell that meets the base region
    /// grown by link_diameter / 2 (base_inside) or the box of half-side
    /// tool_length + 1 mm round `point` (otherwise) and is not inside a shell
    /// obstacle, no cell that meets the other side, none on the grid's
    /// border, and every face neighbour of one of them that they do not hold
    /// lies inside one of `obstacles` grown by link_diameter / 2.
    std::vector<CellRun> cells;
};

struct EnclosureWitness {
    std::vector<Enclosure> walls;  ///< one per base region
};

}  // namespace modsynth::prove
