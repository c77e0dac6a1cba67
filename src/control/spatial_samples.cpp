#include <modsynth/control/spatial_samples.h>

#include <cmath>

#include <modsynth/geometry/vec.h>
#include <modsynth/task/spatial_strokes.h>

namespace modsynth::control {

int primitive_index(const task::SpatialTask& task, const Sample& sample) {
    return task::stroke_first(task, sample.stroke) + sample.primitive;
}

namespace {

/// Arc length of half a turn about the primitive's axis (the whole of a
/// line): how far the nearest point may move from one sample to the next.
double half_turn(const geometry::Primitive3& p) {
    const double len = geometry::length(p);
    // Every kind is named, so that a new one fails the build here.
    return std::visit(
        [&](const auto& x) -> double {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, geometry::Line3>) {
                return len;
            } else if constexpr (std::is_same_v<T, geometry::Helix3>) {
                return len / (2.0 * x.turns);
            } else {
                static_assert(std::is_same_v<T, geometry::Arc3> ||
                              std::is_same_v<T, geometry::Circle3>);
                return geometry::kPi * x.turn.radius;
            }
        },
        p);
}

}  // namespace

void recover_parameters(const task::SpatialTask& task, const kinematics::DhChain& chain,
                        std::vector<Sample>& samples) {
    constexpr double kSnap = 1e-5;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        Sample& a = samples[i];
        if (a.phase == Phase::Transition) {
            a.s = a.q.empty() ? 0.0 : a.q[0];
            continue;
        }
        if (a.phase == Phase::Travel) {
            a.s = 0.0;
            continue;
        }
        const geometry::Primitive3& prim = task.trajectory[primitive_index(task, a)];
        const double len = geometry::length(prim);
        const geometry::Vec3 ee = kinematics::end_effector(chain, a.q);
        const bool first = i == 0 || samples[i - 1].phase != Phase::Trace ||
                           samples[i - 1].primitive != a.primitive ||
                           samples[i - 1].stroke != a.stroke;
        const double from = first ? 0.0 : samples[i - 1].s;
        const double window = half_turn(prim);
        double s = geometry::nearest_between(prim, ee, from - window, from + window).s;
        if (std::abs(s) < kSnap) s = 0.0;
        if (std::abs(s - len) < kSnap) s = len;
        a.s = s;
    }
}

}  // namespace modsynth::control
