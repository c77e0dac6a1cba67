#pragma once
// Branch-and-prune over the 2-joint design space, in the manner of dReal's
// delta-complete decision procedure. Variables: the base (x, y) in a base
// region, the link lengths r1, r2 within the task's bounds, and at every
// checked path point p the absolute angle of the first link, theta (the
// joint angles there: q1 = theta, and q2 follows from the elbow that link 2
// joins to p). Constraints, at each checked point p:
//   elbow e = base + r1 (cos theta, sin theta),  |p - e| = r2,
//   segments base-e and e-p at least (obstacle radius + link_diameter / 2)
//   from every obstacle centre (formats.md, guarantee 3).
// Every robot that traces the path meets these at every path point,
// whichever elbow branch it uses there (a branch may change between points
// through a straight or folded arm: theta ranges over the whole circle, so
// both branches are covered), so a proof that no box survives is a proof
// that no 2-joint robot the task allows exists.
//
// Pruning: each theta range is contracted with an HC4 contractor on the
// two distance constraints (geometry/distance_contractor.h), and refuted
// when a link must enter a no-go disc for every value in the box (a
// Lipschitz bound: a segment moves no farther than its ends). The design
// box is contracted to the hull, over the surviving theta ranges, of what
// they allow (constructive disjunction), per point. Branching bisects the
// widest of base x, base y, r1, r2.
#include <modsynth/geometry/vec.h>
#include <modsynth/run/deadline.h>
#include <modsynth/task/task.h>

#include <optional>
#include <string>
#include <vector>

namespace modsynth::prove {

struct BranchAndBoundOptions {
    /// m: a design box whose sides are all at most delta, and that no check
    /// refutes, ends the search as "a design within delta" (dReal's
    /// delta-sat). It bounds how much the constraints may be violated by
    /// the box's centre design (BranchAndBoundResult::violation is measured,
    /// not assumed). 2 mm: well under the link diameter of any task.
    double delta = 0.002;
    /// Seconds before the search gives up as unknown.
    double time_limit = 2.0;
    /// Design boxes examined, at most, before the search gives up.
    long max_boxes = 200000;
    /// m between the path points checked (every point the end-effector must
    /// visit serves; more points prune more, and cost more per box), and the
    /// number of points, at most (evenly spread over the path when more).
    double point_spacing = 0.02;
    int max_points = 48;
    /// Theta ranges kept per path point and design box, at most: past this a
    /// range is kept whole instead of bisected (sound, only less sharp).
    int max_angle_ranges = 256;
    /// Seconds for a proof and the shrinking of its obstacles to a minimal
    /// core, in all, counted from the proof's start: the shrinking gets what
    /// the proof leaves (prove_two_joint_infeasible; 0 or less than the proof
    /// took: the core lists every obstacle that refuted some box, unshrunk).
    double core_time_limit = 0.0;
    /// Seconds, at most, for each re-run of the search on fewer obstacles
    /// while shrinking. Without a needed obstacle the search must reach a
    /// box to show it needed; a re-run that stops at this budget instead
    /// leaves the core marked not minimised.
    double core_run_time_limit = 2.0;

    /// False (with `error` naming the field) when some value is out of range.
    bool IsValid(std::string* error) const;
};

/// A box of 2-joint designs: base in [base_min, base_max], link lengths in
/// [r1_min, r1_max] x [r2_min, r2_max].
struct DesignBox {
    int base_region = 0;
    geometry::Vec2 base_min = geometry::Vec2::Zero();
    geometry::Vec2 base_max = geometry::Vec2::Zero();
    double r1_min = 0.0, r1_max = 0.0;
    double r2_min = 0.0, r2_max = 0.0;
};

struct BranchAndBoundResult {
    enum class Outcome {
        Infeasible,  ///< every box refuted: no 2-joint design exists
        Box,         ///< a box of side <= delta that nothing refutes
        Unknown,     ///< out of time or boxes first
    };
    Outcome outcome = Outcome::Unknown;
    /// Infeasible: the obstacles whose clearance refuted some box or angle
    /// range on the way, and the primitives of the points that did.
    std::vector<int> obstacles;
    std::vector<int> primitives;
    /// Box: where the refinement should start; its centre design misses the
    /// checked constraints by at most `violation` m (the largest shortfall
    /// of reach or clearance over the checked points, with the better elbow
    /// at each).
    std::optional<DesignBox> box;
    double violation = 0.0;
    long boxes = 0;        ///< design boxes examined
    int points = 0;        ///< path points checked
    double seconds = 0.0;  ///< wall clock
};

/// Searches the 2-joint designs of `task` among the listed obstacles only
/// (fewer obstacles: fewer refutations). Needs base regions (a base that
/// may stand anywhere has no box to start from): Unknown without. Throws
/// std::invalid_argument when the options are not valid.
BranchAndBoundResult branch_and_bound(const task::Task& task, const std::vector<int>& obstacles,
                                      const BranchAndBoundOptions& options = {},
                                      run::Deadline deadline = {});

}  // namespace modsynth::prove
