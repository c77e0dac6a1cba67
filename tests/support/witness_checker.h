#pragma once
// Re-checks the witnesses of obstacle proofs from the task alone, with none
// of the code that found them: sampling, ray casting and a roadmap of its
// own. An empty answer means the witness holds; otherwise it says what fails.
#include <modsynth/prove/wall_witness.h>
#include <modsynth/task/task.h>

#include <string>

namespace modsynth::testing {

std::string check_separation_witness(const task::Task& task, const prove::SeparationWitness& w);

/// Also searches a roadmap of its own (points around every no-go circle and
/// across the base region) for a way shorter than the claimed lower bound.
std::string check_geodesic_witness(const task::Task& task, const prove::GeodesicWitness& w);

/// The shortest way the roadmap finds from the region to p (an upper bound
/// on the true shortest way from some point of the region).
/// Among the listed obstacles, or all when the list is empty.
double roadmap_distance(const task::Task& task, const task::BaseRegion& region,
                        const geometry::Vec2& p, int per_circle = 48,
                        const std::vector<int>& among = {});

}  // namespace modsynth::testing
