#pragma once
// Explaining infeasible spatial tasks (formats.md "Spatial tasks") as the
// plane's are explained (explanation.h): the proofs solve has (the reach
// proof, a wall in space, then the spatial front stage's relaxation over
// every allowed joint count), their core as task parts, and the smallest changes of one part
// each that remove the conflict, each re-checked before it is offered.
#include <vector>

#include <modsynth/explanation/explanation.h>
#include <modsynth/synth/solution.h>
#include <modsynth/task/part.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::explanation {

/// The spatial reach proof, else a wall in space (prove/spatial_enclosure.h,
/// with its witness), else the front stage over every allowed joint
/// count (the union of their minimal cores, as solve gives it), within
/// `time_limit` seconds in all.
InfeasibilityProof prove_infeasible(const task::SpatialTask& task, double time_limit);

/// What `explain` says of a spatial task it could not prove infeasible:
/// what a full run `s` found.
std::string unproved_message(const task::SpatialTask& task, const InfeasibilityProof& proof,
                             const synth::Solution& s);

/// For each part of the core that has a relaxer, the smallest change of that
/// part alone after which neither proof holds (bisection, each step a reach
/// check and a front-stage check), re-checked, then tried with the spatial
/// synthesis for `solve_seconds`:
/// - robot.max_link_length: longer links;
/// - robot.dof: more joints, up to 6;
/// - robot.twists: a twist of +-pi/2, which lets the EE change height;
/// - base_regions, base_regions[i]: one region grown on every side;
/// - obstacles[i] (a wall's): the first of them (smallest first) whose
///   removal opens the wall, and the least move of one of them away from
///   the wall's middle that does;
/// - trajectory[j]: the whole path moved towards the nearest base region
///   (once for all primitives), by the least distance that removes the
///   conflict.
/// A moved path or obstacle keeps 1 mm off the other, so that the changed
/// task is one the reader accepts. Everything ends within `time_limit`.
std::vector<Relaxation> suggest_relaxations(const task::SpatialTask& task,
                                            const std::vector<task::TaskPart>& core,
                                            double solve_seconds, double time_limit = 1e6,
                                            const RelaxationOptions& options = {});

}  // namespace modsynth::explanation
