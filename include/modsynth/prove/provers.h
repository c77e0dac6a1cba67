#pragma once
// The proofs of infeasibility tried before the front stage, in order, by
// solve and explain alike, so that both name the same core: each is exact
// geometry and takes milliseconds, except the branch and bound, which has a
// budget of its own.
#include <functional>
#include <optional>
#include <vector>

#include <modsynth/prove/branch_and_bound.h>
#include <modsynth/prove/proof.h>
#include <modsynth/run/deadline.h>
#include <modsynth/task/task.h>

namespace modsynth::prove {

struct Prover {
    const char* name;  ///< how progress names it: "reach", "obstacles"
    std::function<std::optional<Proof>(const task::Task&, const run::Deadline&)> prove;
};

/// A primitive out of reach of the longest arm (reach_proof.h); a closed
/// wall or a detour longer than any arm (obstacle_proof.h); for tasks of 2
/// joints only, a loop of the path round an obstacle (loop_proof.h), then
/// the branch and bound with `two_joint`'s options (skipped when its
/// time_limit is 0).
std::vector<Prover> provers(const BranchAndBoundOptions& two_joint);

}  // namespace modsynth::prove
