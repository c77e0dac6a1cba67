#include <modsynth/control/spatial_samples.h>

#include <algorithm>
#include <cmath>

#include <modsynth/geometry/primitive3.h>
#include <modsynth/geometry/vec.h>
#include <modsynth/task/spatial_strokes.h>

#include "sample_parameters.h"

namespace modsynth::control {

void recover_parameters(const task::SpatialTask& task, const kinematics::DhChain& chain,
                        std::vector<Sample>& samples) {
    recover_parameters_with(
        task, samples, [&](std::size_t i, const geometry::Primitive3& prim, bool first) {
            const geometry::Vec3 ee = kinematics::end_effector(chain, samples[i].q);
            const double from = first ? 0.0 : samples[i - 1].s;
            // The nearest point within half a turn of the last sample's: a
            // helix passes near its own start once a turn.
            const double window =
                std::min(geometry::half_turn_length(prim), geometry::length(prim));
            return geometry::nearest_between(prim, ee, from - window, from + window).s;
        });
}

}  // namespace modsynth::control
