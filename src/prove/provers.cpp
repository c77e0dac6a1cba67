#include <modsynth/prove/provers.h>

#include <modsynth/prove/conflict_text.h>
#include <modsynth/prove/loop_proof.h>
#include <modsynth/prove/obstacle_proof.h>
#include <modsynth/prove/reach_proof.h>
#include <modsynth/prove/spatial_enclosure.h>
#include <modsynth/prove/spatial_reach_proof.h>

namespace modsynth::prove {

std::vector<Prover> provers(const BranchAndBoundOptions& two_joint) {
    return {
        {"reach",
         [](const task::Task& task, const run::Deadline&) -> std::optional<Proof> {
             auto core = out_of_reach_core(task);
             if (!core) return std::nullopt;
             Proof proof;
             proof.message = describe_conflict(task, *core);
             proof.core = std::move(*core);
             return proof;
         }},
        {"obstacles", [](const task::Task& task,
                         const run::Deadline&) { return prove_obstacle_infeasible(task); }},
        {"loop",
         [](const task::Task& task, const run::Deadline&) -> std::optional<Proof> {
             if (task.robot.dof != std::vector<int>{2}) return std::nullopt;
             return prove_two_joint_loop(task);
         }},
        {"obstacles",
         [two_joint](const task::Task& task,
                     const run::Deadline& deadline) -> std::optional<Proof> {
             if (!(two_joint.time_limit > 0.0)) return std::nullopt;
             return prove_two_joint_infeasible(task, two_joint, deadline);
         }},
    };
}

std::vector<SpatialProver> spatial_provers(double enclosure_seconds) {
    return {
        {"reach",
         [](const task::SpatialTask& task, const run::Deadline&) -> std::optional<Proof> {
             auto core = spatial_out_of_reach_core(task);
             if (!core) return std::nullopt;
             Proof proof;
             proof.message = describe_spatial_reach(task, *core);
             proof.core = std::move(*core);
             return proof;
         }},
        // Milliseconds where no obstacle comes near a shell, within
        // enclosure_seconds otherwise.
        {"walls",
         [enclosure_seconds](const task::SpatialTask& task, const run::Deadline& deadline) {
             return prove_spatial_enclosure(task, deadline.within(enclosure_seconds));
         }},
    };
}

}  // namespace modsynth::prove
