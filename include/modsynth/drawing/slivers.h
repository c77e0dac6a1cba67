#pragma once
// Slivers: pieces shorter than the tolerance that fitting leaves in a
// chain (a path optimiser's leftover arc of a few micrometres between two
// arcs). A robot traces them like any piece, and a primitive that short
// is noise in the task: they are merged into their neighbours.
#include <span>
#include <vector>

#include <modsynth/drawing/curve.h>
#include <modsynth/drawing/deadline.h>
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
///
/// What that leaves is then replaced run by run: a run of consecutive
/// short pieces as a whole, by the nearest of one line over it, the
/// neighbouring lines extended to meet, one arc or line over it and a
/// window of a neighbour, a biarc over both windows; a loop smaller than
/// the tolerance collapses to the point where it leaves the stroke; a run
/// at a stroke's end is dropped (a short line past a corner: the stroke
/// ends at the corner); a long run (a curve drawn as a polyline of short
/// lines) by the longest stretches one line or arc replaces; a run where
/// the chain turns back (a hairpin) by a cusp at its tip. Given the
/// `drawing` the chain was fitted to (its curves), these merges are measured against
/// it (both ways, near the merge: a point of the drawing the replaced
/// pieces passed near stays as near the chain) rather than added to
/// `deviation`, which the fitting leaves close to the tolerance. Only a stroke shorter than
/// the tolerance as a whole keeps pieces that short. Throws ImportTimeout
/// once `deadline` has passed, the chain then half merged.
double merge_slivers(std::vector<geometry::Primitive>& chain, double tolerance, double deviation,
                     std::span<const Curve> drawing = {}, Clock::time_point deadline = kNoDeadline);

/// The same, run by run, for strokes joined end to end from several
/// curves (a CAD polyline written as LINE entities: each curve one piece,
/// each stroke a run of them), measured against all of the `drawing`'s
/// curves: a point of it that another stroke passes as near as the
/// replaced pieces did stays drawn. Returns the deviation after merging; throws ImportTimeout once
/// `deadline` has passed.
double merge_stroke_slivers(std::vector<std::vector<geometry::Primitive>>& strokes,
                            double tolerance, double deviation, std::span<const Curve> drawing,
                            Clock::time_point deadline = kNoDeadline);

}  // namespace modsynth::drawing
