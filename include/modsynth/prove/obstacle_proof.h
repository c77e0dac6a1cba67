#pragma once
// Obstacle infeasibility, proved by geometry before any solver runs: a
// closed wall between the base regions and the path (separation.h), or a
// detour around the obstacles longer than any arm (geodesic_reach.h). Both
// hold for every allowed joint count and every link length.
#include <modsynth/prove/branch_and_bound.h>
#include <modsynth/prove/proof.h>
#include <modsynth/task/task.h>

#include <optional>
#include <string>
#include <vector>

namespace modsynth::prove {

/// A proof when the obstacles make the task infeasible in one of these two
/// ways (always minimal, with its witness); nullopt otherwise (also when the path itself runs into
/// a no-go disc everywhere, or when the path is out of reach without any obstacle: the front stage
/// proves those).
std::optional<Proof> prove_obstacle_infeasible(const task::Task& task);

/// Tasks whose only allowed joint count is 2 (and that have base regions
/// and obstacles): a proof by branch and bound (branch_and_bound.h) that no
/// 2-joint design reaches the path's points with its links clear; nullopt
/// when the search finds a box or runs out of its budget. The core lists the
/// obstacles of the proof, the primitives of the refuting points,
/// base_regions, robot.dof and the link bounds. The obstacles are shrunk by
/// a deletion filter (each deletion a re-run of the search on fewer
/// obstacles, at most options.core_run_time_limit each) until without any
/// one of them the search finds no proof, within what the first proof left
/// of options.core_time_limit; past it (`minimal` false) the core keeps
/// the obstacles proved so far, and the message says it is not minimised.
std::optional<Proof> prove_two_joint_infeasible(const task::Task& task,
                                                const BranchAndBoundOptions& options,
                                                run::Deadline deadline = {});

/// "0-8", "2, 5, 7-9": obstacle indices in words.
std::string index_ranges(std::vector<int> indices);

}  // namespace modsynth::prove
