#include <modsynth/synth/split_circles.h>

#include <algorithm>
#include <cassert>
#include <cmath>

#include <modsynth/task/strokes.h>

namespace modsynth::synth {

using geometry::Primitive;
using geometry::PrimitiveKind;
using geometry::Vec2;

SplitTask split_circles(const task::Task& task, int arcs) {
    assert(arcs >= 2);
    SplitTask out;
    out.task = task;
    out.task.trajectory.clear();
    out.task.stroke_starts.clear();
    for (int j = 0; j < static_cast<int>(task.trajectory.size()); ++j) {
        if (task::has_strokes(task) && task::index_in_stroke(task, j) == 0)
            out.task.stroke_starts.push_back(static_cast<int>(out.task.trajectory.size()));
        const Primitive& p = task.trajectory[j];
        if (p.kind != PrimitiveKind::Circle) {
            out.task.trajectory.push_back(p);
            out.pieces.push_back({j, 0.0, true});
            continue;
        }
        // The cut points on the circle by angle, the last the circle's own
        // start, so that the arcs join it exactly where the stroke does.
        double offset = 0.0;
        Vec2 from = p.start;
        for (int k = 0; k < arcs; ++k) {
            const double angle = p.start_angle + p.sweep * (k + 1) / arcs;
            const Vec2 to =
                k + 1 == arcs ? p.start : Vec2(p.center + p.radius * geometry::unit(angle));
            const Primitive arc = geometry::make_arc(from, to, p.center, p.sweep > 0.0);
            out.task.trajectory.push_back(arc);
            out.pieces.push_back({j, offset, k + 1 == arcs});
            offset += geometry::length(arc);
            from = to;
        }
    }
    return out;
}

std::vector<control::Sample> join_arcs(const task::Task& original, const SplitTask& split,
                                       std::vector<control::Sample> samples) {
    double along = 0.0;  // the last trace sample's arc length along its original
    int tracing = -1;    // ... and that original, while its trace runs
    for (control::Sample& a : samples) {
        const SplitTask::Piece& piece =
            split.pieces.at(static_cast<std::size_t>(control::primitive_index(split.task, a)));
        const int in_stroke = piece.original - task::stroke_first(original, a.stroke);
        const bool rest = a.phase == control::Phase::Transition && !piece.last;
        if (a.phase == control::Phase::Trace || rest) {
            const double length = geometry::length(original.trajectory[piece.original]);
            const double s = rest ? along : std::min(length, piece.offset + a.s);
            // Rounding of the offsets must not read as a step back.
            along = tracing == piece.original ? std::max(along, s) : s;
            tracing = piece.original;
            a.phase = control::Phase::Trace;
            a.s = along;
        } else {
            tracing = -1;
        }
        a.primitive = in_stroke;
    }
    return samples;
}

}  // namespace modsynth::synth
