#pragma once
// What the planar and the spatial verifier check alike, whatever the arm:
// that the samples name strokes and primitives of the task and hold one
// angle per joint, and the order of formats.md guarantee 1 (every
// primitive traced in order from its start to its end, progress never
// back and never more than the step the bounds between samples assume, nor
// half a turn of an arc, transitions and travel only where they belong).
// Each verifier derives its Checker from this base and adds the geometry.
#include <string>
#include <utility>
#include <vector>

#include <modsynth/control/sample.h>
#include <modsynth/text/format.h>
#include <modsynth/verify/verifier.h>

namespace modsynth::verify {

template <class Task>
class CheckerBase {
protected:
    using Phase = control::Phase;
    using Sample = control::Sample;

    CheckerBase(const Task& task, const std::vector<Sample>& samples, const VerifyOptions& options)
        : task_(task), samples_(samples), opt_(options) {}

    void violation(Violation::Kind kind, int i, double amount, std::string message,
                   int obstacle = -1, int link = -1) {
        Violation v;
        v.kind = kind;
        v.sample = i;
        if (i >= 0) {
            const Sample& a = samples_[static_cast<std::size_t>(i)];
            v.primitive = control::primitive_index(task_, a);
            v.transition = a.phase == Phase::Transition;
            v.travel = a.phase == Phase::Travel;
            v.s = a.s;
        }
        v.obstacle = obstacle;
        v.link = link;
        v.amount = amount;
        v.message = std::move(message);
        cert_.violations.push_back(std::move(v));
    }

    void structure(const std::string& message) {
        violation(Violation::Kind::Structure, -1, 0.0, message);
    }

    /// Every sample names a stroke and a primitive of the task and holds
    /// `dof` joint angles; sets structure_ok_ when nothing is wrong so far.
    void check_samples(int dof) {
        if (samples_.empty()) structure("no samples");
        for (std::size_t i = 0; i < samples_.size(); ++i) {
            const Sample& a = samples_[i];
            if (a.stroke < 0 || a.stroke >= task::stroke_count(task_)) {
                structure("stroke " + std::to_string(a.stroke) + " of sample " + std::to_string(i) +
                          " is not in the task");
                break;
            }
            if (a.primitive < 0 || a.primitive > task::stroke_last(task_, a.stroke) -
                                                     task::stroke_first(task_, a.stroke)) {
                structure("primitive " + std::to_string(a.primitive) + " of sample " +
                          std::to_string(i) + " is not in the task");
                break;
            }
        }
        for (std::size_t i = 0; i < samples_.size(); ++i) {
            if (static_cast<int>(samples_[i].q.size()) != dof) {
                violation(Violation::Kind::Structure, static_cast<int>(i), 0.0,
                          "sample has the wrong number of joint angles");
                break;
            }
        }
        structure_ok_ = cert_.violations.empty();
    }

    /// Guarantee 1's order. A trace may begin one step past its start
    /// right after the trace of the primitive before, whose last sample
    /// stands at the junction, when `past_junction` (the planar planner
    /// repeats no pose there; the pair across is then checked as one).
    void check_order(bool past_junction) {
        const int m = static_cast<int>(task_.trajectory.size());
        int expected = 0;
        for (std::size_t i = 0; i < samples_.size(); ++i) {
            const Sample& a = samples_[i];
            const int j = control::primitive_index(task_, a);
            const std::string name = task::part_name(task_, j);
            const bool first = control::starts_run(samples_, i);
            const int at = static_cast<int>(i);
            if (a.phase == Phase::Trace && first) {
                const bool after_junction = past_junction && i > 0 &&
                                            control::junction(samples_[i - 1], a) && a.s > 0.0 &&
                                            a.s <= opt_.max_ee_step + 1e-12;
                if (j != expected || (a.s != 0.0 && !after_junction))
                    violation(Violation::Kind::Order, at, 0.0,
                              "trace of " + name + " out of order or not from its start");
                expected = j + 1;
            }
            if (a.phase == Phase::Transition &&
                (j != expected - 1 || !task::has_transition_after(task_, j)))
                violation(Violation::Kind::Order, at, 0.0, "transition out of place");
            if (a.phase == Phase::Travel &&
                (j != expected - 1 || j + 1 >= m || !task::ends_stroke(task_, j)))
                violation(Violation::Kind::Order, at, 0.0, "travel out of place");
            const auto& prim = task_.trajectory[static_cast<std::size_t>(j)];
            if (!first && a.phase == Phase::Trace) {
                const double step = a.s - samples_[i - 1].s;
                if (step < 0.0 || step > opt_.max_ee_step + 1e-12)
                    violation(Violation::Kind::Order, at, 0.0,
                              text::format("progress step %.6f m between samples", step));
                // Progress along a turn is read as an angle unwrapped between
                // samples: a step of half a turn or more reads as one back,
                // and the bounds between samples assume less.
                const double half_turn = geometry::half_turn_length(prim);
                if (step >= half_turn)
                    violation(Violation::Kind::Order, at, 0.0,
                              text::format("progress step %.6f m between samples, half a turn "
                                           "or more of a turn of %.6f m",
                                           step, 2.0 * half_turn));
            }
            if (a.phase == Phase::Trace && control::ends_run(samples_, i) &&
                std::abs(a.s - geometry::length(prim)) > 1e-9)
                violation(Violation::Kind::Order, at, 0.0,
                          "trace of " + name + " stops before its end");
        }
        if (expected != m)
            violation(Violation::Kind::Order, -1, 0.0, "the motion does not trace every primitive");
    }

    Certificate finish() {
        cert_.ok = cert_.violations.empty() && cert_.coarse_pairs.empty();
        return std::move(cert_);
    }

    const Task& task_;
    const std::vector<Sample>& samples_;
    VerifyOptions opt_;
    Certificate cert_;
    bool structure_ok_ = false;
};

}  // namespace modsynth::verify
