#pragma once
// Slivers: pieces shorter than the tolerance that fitting leaves in a
// chain (a path optimiser's leftover arc of a few micrometres between two
// arcs). A robot traces them like any piece, and a primitive that short
// is noise in the task: they are merged into their neighbours.
#include <vector>

#include <modsynth/geometry/primitive.h>

namespace modsynth::drawing {

/// Merges each primitive shorter than `tolerance` in a chain of more than
/// one into its neighbours: between two pieces it meets tangentially, the
/// three become a biarc over the sliver and a stretch of each neighbour
/// (tangent-continuous at both ends and inside); next to a corner, it is
/// folded into the neighbour on its smooth side by one arc that keeps that
/// side's tangent, and the corner stays. The chain stays joined, no new
/// piece is shorter than the tolerance, and a merge is made only when what
/// replaces the pieces stays within what `tolerance` leaves beside
/// `deviation` (the fitted chain's own distance from the drawing). Returns
/// the deviation after merging. Circles are left alone.
double merge_slivers(std::vector<geometry::Primitive>& chain, double tolerance, double deviation);

}  // namespace modsynth::drawing
