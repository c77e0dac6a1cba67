#pragma once
// One sample of the control (formats.md "samples"), for a planar arm or a
// DH chain alike, and how runs of samples are told apart.
#include <cassert>
#include <cstddef>
#include <vector>

#include <modsynth/task/strokes.h>

namespace modsynth::control {

/// Travel: the pen-up motion between two strokes (formats.md "Several
/// strokes"), the EE free.
enum class Phase { Trace, Transition, Travel };

struct Sample {
    double t = 0.0;
    Phase phase = Phase::Trace;
    /// As in the document: the index within `stroke` (task/strokes.h maps it
    /// to task.trajectory, see primitive_index below). In travel the last
    /// primitive of the stroke just finished.
    int primitive = 0;
    /// Where along the motion: arc length along the primitive for trace
    /// samples, the first joint's angle (or the sweep's fraction) for
    /// transition samples, 0 in travel.
    double s = 0.0;
    std::vector<double> q;
    int stroke = 0;
    /// Joint rates (rad/s) and accelerations (rad/s^2), as long as q when
    /// the motion is timed for a controller, empty otherwise (formats.md,
    /// "Timing a controller accepts"). Braced, so that a sample written as
    /// {t, phase, primitive, s, q, stroke} leaves them empty without a
    /// missing-initializer warning.
    std::vector<double> qd{}, qdd{};
};

/// The index in task.trajectory of the primitive a sample belongs to.
template <task::StrokedTask T>
int primitive_index(const T& task, const Sample& sample) {
    const int j = task::primitive_index(task, sample.stroke, sample.primitive);
    assert(j >= 0 && j < static_cast<int>(task.trajectory.size()));
    return j;
}

/// Whether a and b belong to one run: the same phase of the same primitive
/// of the same stroke.
inline bool same_run(const Sample& a, const Sample& b) {
    return a.phase == b.phase && a.primitive == b.primitive && a.stroke == b.stroke;
}

/// Sample i begins its run, or ends it.
inline bool starts_run(const std::vector<Sample>& samples, std::size_t i) {
    return i == 0 || !same_run(samples[i - 1], samples[i]);
}
inline bool ends_run(const std::vector<Sample>& samples, std::size_t i) {
    return i + 1 == samples.size() || !same_run(samples[i], samples[i + 1]);
}

/// a traces a primitive and b the next one of the same stroke.
inline bool junction(const Sample& a, const Sample& b) {
    return a.phase == Phase::Trace && b.phase == Phase::Trace && a.stroke == b.stroke &&
           b.primitive == a.primitive + 1;
}

}  // namespace modsynth::control
