#include <modsynth/synth/split_circles.h>

#include <cmath>

#include <catch2/catch.hpp>

#include <modsynth/geometry/primitive.h>
#include <modsynth/synth/synthesizer.h>
#include <modsynth/task/strokes.h>
#include <modsynth/verify/verifier.h>

namespace {

using namespace modsynth;
using control::Phase;
using control::Sample;
using geometry::Vec2;

// Two strokes: a line, then a clockwise circle and a line after it.
task::Task two_strokes() {
    task::Task t;
    t.name = "strokes";
    t.trajectory.push_back(geometry::make_line(Vec2(0.3, 0.3), Vec2(0.4, 0.3)));
    t.trajectory.push_back(geometry::make_circle(Vec2(0.9, 0.0), Vec2(0.6, 0.0), false));
    t.trajectory.push_back(geometry::make_line(Vec2(0.9, 0.0), Vec2(0.9, 0.2)));
    t.stroke_starts = {0, 1};
    return t;
}

}  // namespace

TEST_CASE("a circle is cut into arcs that trace it, and strokes stay as they were",
          "[split_circles]") {
    const task::Task t = two_strokes();
    const synth::SplitTask split = synth::split_circles(t, 8);
    REQUIRE(split.task.trajectory.size() == 10);
    REQUIRE(split.pieces.size() == 10);
    CHECK(split.task.stroke_starts == std::vector<int>{0, 1});
    double total = 0.0;
    for (int k = 1; k <= 8; ++k) {
        const geometry::Primitive& arc = split.task.trajectory[k];
        CHECK(arc.kind == geometry::PrimitiveKind::Arc);
        CHECK(arc.sweep < 0.0);  // clockwise, as the circle
        CHECK(split.pieces[k].original == 1);
        CHECK(split.pieces[k].offset == Approx(total).margin(1e-12));
        CHECK(split.pieces[k].last == (k == 8));
        // Joined end to end, and round the circle's centre.
        const geometry::Vec2 from =
            k == 1 ? t.trajectory[1].start : split.task.trajectory[k - 1].end;
        CHECK((arc.start - from).norm() < 1e-12);
        for (const double f : {0.0, 0.3, 1.0})
            CHECK((geometry::point_at(arc, f * geometry::length(arc)) - Vec2(0.6, 0.0)).norm() ==
                  Approx(0.3));
        total += geometry::length(arc);
    }
    CHECK(split.task.trajectory[8].end == t.trajectory[1].start);  // exactly: the stroke goes on
    CHECK(total == Approx(geometry::length(t.trajectory[1])).epsilon(1e-12));
    CHECK(split.pieces[9].original == 2);
    CHECK(split.pieces[0].original == 0);
}

TEST_CASE("a motion of the arcs reads back as one of the circle, transitions as rests",
          "[split_circles]") {
    const task::Task t = two_strokes();
    const synth::SplitTask split = synth::split_circles(t, 2);
    const double half = geometry::length(split.task.trajectory[1]);
    const std::vector<double> q{0.1, 0.2, 0.3};
    // Stroke 1 of the split task: arc 0, a transition, arc 1, a transition
    // after the circle (before the line), the line.
    const std::vector<Sample> motion{
        {0.0, Phase::Trace, 0, 0.0, q, 1},      {0.1, Phase::Trace, 0, half, q, 1},
        {0.2, Phase::Transition, 0, 1.0, q, 1}, {0.3, Phase::Transition, 0, 1.5, q, 1},
        {0.4, Phase::Trace, 1, 0.0, q, 1},      {0.5, Phase::Trace, 1, half, q, 1},
        {0.6, Phase::Transition, 1, 2.0, q, 1}, {0.7, Phase::Trace, 2, 0.0, q, 1},
        {0.8, Phase::Trace, 2, 0.2, q, 1}};
    const std::vector<Sample> joined = synth::join_arcs(t, split, motion);
    REQUIRE(joined.size() == motion.size());
    // The arcs and the rest between them: the circle's trace, not going back.
    for (int i = 0; i <= 5; ++i) {
        CHECK(joined[i].phase == Phase::Trace);
        CHECK(joined[i].primitive == 0);
        CHECK(joined[i].stroke == 1);
        if (i > 0) CHECK(joined[i].s >= joined[i - 1].s);
    }
    CHECK(joined[2].s == joined[1].s);
    CHECK(joined[3].s == joined[1].s);
    CHECK(joined[4].s == Approx(half));
    CHECK(joined[5].s == Approx(geometry::length(t.trajectory[1])).epsilon(1e-12));
    CHECK(joined[5].s <= geometry::length(t.trajectory[1]));
    // The transition after the circle stays one, its s the first joint's.
    CHECK(joined[6].phase == Phase::Transition);
    CHECK(joined[6].primitive == 0);
    CHECK(joined[6].s == 2.0);
    CHECK(joined[7].primitive == 1);
    CHECK(joined[8].s == 0.2);
}

TEST_CASE("a circle round a post is traced by three joints that turn the first link inside it",
          "[split_circles][synthesizer]") {
    // scripts/loop-tasks --shape circle: radius 0.3 m round a post of 0.05 m
    // at its centre, 0.6 m from the base.
    task::Task t;
    t.name = "circle";
    const Vec2 c(0.6, 0.0);
    t.trajectory.push_back(geometry::make_circle(c + Vec2(0.3, 0.0), c, true));
    t.obstacles.push_back({c, 0.05});
    t.base_regions.push_back({Vec2(-0.01, -0.01), Vec2(0.01, 0.01)});
    t.robot.dof = {2, 3};
    synth::SynthesisOptions o;
    o.time_limit = 60.0;
    const synth::Solution s = synth::synthesize(t, o);
    REQUIRE(s.status == synth::Status::Solved);
    CHECK(s.robot.dof() == 3);
    // Certified against the circle as written, every sample on it.
    CHECK(verify::certify(t, s.robot, s.samples, synth::verify_options_for(t, o)).ok);
    for (const Sample& a : s.samples) CHECK(a.primitive == 0);
    // The first link turns while the tool traces.
    double lo = s.samples.front().q[0], hi = lo;
    for (const Sample& a : s.samples) {
        lo = std::min(lo, a.q[0]);
        hi = std::max(hi, a.q[0]);
    }
    CHECK(hi - lo > 0.1);
}
