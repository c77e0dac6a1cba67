#pragma once
// Initial guesses for the spatial refinement: a cheap, deterministic random
// search over the designs of one skeleton (the family draws them: a base in
// its region, lengths and offsets), each scored by its worst margin at
// points along the path with the family's closed-form IK: the pose limits
// (an elbow's room from its fold and stretch, the path's distance from a
// yaw axis), the self-collision rules and the obstacles' clearance. The IK
// branch of each stroke, and its free numbers (a hand's pitch), are the
// ones that score best. Clear candidates rank shortest first, as in the
// plane.
#include <string>
#include <vector>

#include <modsynth/arms/family.h>
#include <modsynth/kinematics/arm_model.h>
#include <modsynth/nlp/spatial_formulation.h>
#include <modsynth/run/deadline.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::synth {

struct ScoredDesign {
    kinematics::ArmDesign design;
    /// Worst margin (m) at the scoring points; >= 0: clear at all of them.
    double margin = 0.0;
};

struct SpatialGuessOptions {
    /// m between the path points every candidate is scored at, and at most
    /// this many points over the whole path (the spacing widens past it).
    double scoring_spacing = 0.02;
    int max_points = 400;
    /// Random candidates drawn per skeleton; they are scored shortest
    /// first, and most stop at their first unclear point.
    int candidates = 600;
    /// m: candidates whose base and every value differ by less than this
    /// count as one start.
    double distinct_distance = 0.02;

    /// False (with `error` naming the field) when some value is out of range.
    bool IsValid(std::string* error) const;
};

/// m: the chain's length of a design (sum |a_k| + |d_k|).
double chain_length(const kinematics::ArmDesign& design);

/// The worst margin of a design over points every `spacing` m of the path
/// (at most `max_points`), with the margins of the refinement.
double design_margin(const task::SpatialTask& task, const kinematics::ArmDesign& design,
                     const nlp::SpatialMargins& margins, double spacing, int max_points);

/// Up to `count` distinct candidates, best first: clear ones by shorter
/// chain, then the others by larger margin. Scoring stops at the deadline.
/// Throws std::invalid_argument when the options are not valid.
std::vector<ScoredDesign> spatial_initial_guesses(const task::SpatialTask& task,
                                                  const arms::Skeleton& skeleton, int count,
                                                  unsigned seed, const nlp::SpatialMargins& margins,
                                                  const run::Deadline& deadline = {},
                                                  const SpatialGuessOptions& options = {});

}  // namespace modsynth::synth
