#pragma once
// Obstacle infeasibility, proved by geometry before any solver runs: a
// closed wall between the base regions and the path (separation.h), or a
// detour around the obstacles longer than any arm (geodesic_reach.h). Both
// hold for every allowed joint count and every link length.
#include <modsynth/synth/wall_witness.h>
#include <modsynth/task/task.h>

#include <optional>
#include <string>
#include <vector>

namespace modsynth::synth {

struct ObstacleProof {
    /// Task parts of the proof, minimal: without any one obstacle listed,
    /// the same kind of proof no longer holds.
    std::vector<std::string> core;
    std::string message;  ///< the proof in words (no "Proved infeasible: ")
    std::optional<SeparationWitness> separation;
    std::optional<GeodesicWitness> geodesic;
};

/// A proof when the obstacles make the task infeasible in one of these two
/// ways; nullopt otherwise (also when the path itself runs into a no-go disc
/// everywhere, or when the path is out of reach without any obstacle: the
/// front stage proves those).
std::optional<ObstacleProof> prove_obstacle_infeasible(const task::Task& task);

/// "0-8", "2, 5, 7-9": obstacle indices in words.
std::string index_ranges(std::vector<int> indices);

}  // namespace modsynth::synth
