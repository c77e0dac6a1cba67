#pragma once
// Certified verification of a spatial motion (formats.md "Spatial tasks"):
// the five spatial guarantees checked exactly at the samples and proved
// between them with the second-order bounds of docs/verification.md
// ("Spatial chains"), with the same Certificate as in the plane so that the
// synthesis acts on it alike (violations at samples, coarse_pairs to
// split).
#include <vector>

#include <modsynth/control/motion.h>
#include <modsynth/kinematics/dh_chain.h>
#include <modsynth/task/spatial_task.h>
#include <modsynth/verify/verifier.h>

namespace modsynth::verify {

/// The samples need their `s` (control::recover_parameters for samples read
/// from a file). Violation::link is the 0-based link of the offending
/// segment. Throws std::invalid_argument when the options are not valid.
Certificate certify(const task::SpatialTask& task, const kinematics::DhChain& chain,
                    const std::vector<control::Sample>& samples, const VerifyOptions& options = {});

}  // namespace modsynth::verify
