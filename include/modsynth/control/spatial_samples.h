#pragma once
// Samples of a spatial motion: the same control::Sample as in the plane
// (formats.md "samples"), with the joint angles of a DH chain.
#include <vector>

#include <modsynth/control/motion.h>
#include <modsynth/kinematics/dh_chain.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::control {

/// For samples read from a file, which carry no `s`: the arc length of the
/// EE's nearest point on its primitive, followed from the previous sample of
/// the run within half a turn either way (from the start at a run's first
/// sample), so that a circle's run begins at 0 and a helix's stays on its
/// turn; snapped to the ends within 10 um. In transitions the first joint's
/// angle; 0 in travel.
void recover_parameters(const task::SpatialTask& task, const kinematics::DhChain& chain,
                        std::vector<Sample>& samples);

}  // namespace modsynth::control
