#pragma once
// The proofs of infeasibility tried before the front stage, in order, by
// solve and explain alike, so that both name the same core: each is exact
// geometry and takes milliseconds, except the branch and bound, which has a
// budget of its own.
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include <modsynth/prove/branch_and_bound.h>
#include <modsynth/prove/proof.h>
#include <modsynth/run/deadline.h>
#include <modsynth/task/spatial_task.h>
#include <modsynth/task/task.h>

namespace modsynth::prove {

/// One proof of infeasibility for tasks of one kind.
template <class Task>
struct ProverOf {
    const char* name;  ///< how progress names it: "reach", "obstacles"
    std::function<std::optional<Proof>(const Task&, const run::Deadline&)> prove;
};
using Prover = ProverOf<task::Task>;
using SpatialProver = ProverOf<task::SpatialTask>;

/// The first proof of `provers` for the task, in order, and the name of
/// the prover that found it; nothing when none did.
template <class Task>
std::optional<std::pair<const char*, Proof>> first_proof(const std::vector<ProverOf<Task>>& provers,
                                                         const Task& task,
                                                         const run::Deadline& deadline) {
    for (const ProverOf<Task>& prover : provers)
        if (std::optional<Proof> proof = prover.prove(task, deadline))
            return std::pair<const char*, Proof>{prover.name, std::move(*proof)};
    return std::nullopt;
}

/// A primitive out of reach of the longest arm (reach_proof.h); a closed
/// wall or a detour longer than any arm (obstacle_proof.h); for tasks of 2
/// joints only, a loop of the path round an obstacle (loop_proof.h), then
/// the branch and bound with `two_joint`'s options (skipped when its
/// time_limit is 0).
std::vector<Prover> provers(const BranchAndBoundOptions& two_joint);

/// A primitive out of reach of the longest chain from every base box
/// (spatial_reach_proof.h), then a closed shell of obstacles between the
/// base boxes and the path (spatial_enclosure.h) within `enclosure_seconds`.
std::vector<SpatialProver> spatial_provers(double enclosure_seconds = 1.0);

}  // namespace modsynth::prove
