#pragma once
// Walls in space: obstacles whose grown shapes (each obstacle grown by
// link_diameter / 2, the region guarantee 3 keeps every free point of the
// chain out of) close a shell round every base region, or round a point of
// the path, so that no chain joins the two.
//
// The free part of a chain (all of it but the mount, its first D/2 from the
// base, and the tool, its last tool_length before the EE) is one connected
// curve outside the open grown obstacles, from within D/2 of the base to
// within tool_length of the EE, which comes within 1 mm of every path point. So it suffices to find
// a closed set of grid cells that holds every free cell meeting one side's neighbourhood, meets
// none of the other side's, stays off the grid's border, and whose every
// face neighbour outside it lies inside one open grown obstacle: a curve
// leaving it would have to cross such a cell (a cell's edges and corners
// belong to the cells round them, so face neighbours suffice). A cell lies
// inside a grown obstacle when its eight corners do (the grown shapes are
// convex); that is decided over outward-rounded intervals on corners that
// are exact in binary, so rounding never blocks a cell that is not blocked.
#include <optional>
#include <vector>

#include <modsynth/prove/proof.h>
#include <modsynth/run/deadline.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::prove {

struct EnclosureOptions {
    /// Grid resolutions tried, coarse first: cells along the longest side of
    /// the searched box (the base region, the path and the obstacles near
    /// them). A wall thinner than a few cells needs the finer ones.
    std::vector<int> resolutions{48, 96, 160};
    /// Whether to shrink the core to a minimal one (a deletion filter);
    /// without, the core holds every obstacle next to the enclosed cells.
    bool minimise = true;
};

/// A shell for every base region (the first path point found outside each),
/// its obstacles shrunk by a deletion filter to a minimal set at the same
/// grid (without any one of them the cells no longer close), within the
/// deadline (past it: `minimal` false, the core the sound one found). The
/// core: the shells' obstacles, the primitives of the points, base_regions,
/// robot.link_diameter when the same cells do not close for a tube of
/// diameter 0, robot.tool_length when it is not 0. nullopt when some base
/// region has no shell, and for tasks without base regions or obstacles.
std::optional<Proof> prove_spatial_enclosure(const task::SpatialTask& task,
                                             const run::Deadline& deadline = {},
                                             const EnclosureOptions& options = {});

}  // namespace modsynth::prove
