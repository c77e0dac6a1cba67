#pragma once
// The one search of modsynth, for planar and spatial tasks alike:
//
//   proofs -> per joint count, fewest first: front stage -> skeletons ->
//   initial guesses -> refinement rounds (solve, plan the motion, certify,
//   counterexamples back) -> the first certified design -> shorter
//   variants -> the design choice -> timing;
//   then more guesses for every skeleton until the time is up; then a proof
//   from the front stages' cores, or "unknown" with what was tried.
//
// What differs between the plane and space is a Kind (search_kind.h): the
// geometry of the proofs and the front stage, the arms and their
// refinement, the motion and its verifier. This file holds the order of
// the steps and every decision made between them, once.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <modsynth/control/joint_limits.h>
#include <modsynth/control/path_corners.h>
#include <modsynth/control/retime.h>
#include <modsynth/prove/proof.h>
#include <modsynth/run/stopwatch.h>
#include <modsynth/synth/design_choice.h>
#include <modsynth/synth/synthesizer.h>
#include <modsynth/text/format.h>

#include "search_kind.h"

namespace modsynth::synth {

template <SearchKind Kind>
class SearchFlow {
public:
    using Skeleton = typename Kind::Skeleton;
    using Design = typename Kind::Design;
    using Guess = typename Kind::Guess;
    using Attempt = typename Kind::Attempt;
    using Verdicts = synth::Verdicts<Skeleton>;

    SearchFlow(Kind& kind, SearchRun& run) : k_(kind), r_(run), s_(kind.settings()) {}

    Solution run() {
        if (auto proof = k_.prove()) return infeasible(std::move(*proof));
        Verdicts v;
        if (auto found = first_pass(v)) return timed(std::move(*found));
        // Blocking skeletons proves nothing: while time is left, their
        // other initial guesses are tried (a kind may first drop skeletons
        // a proof rules out).
        k_.prune_retries(v);
        if (!v.searched.empty())
            if (auto found = retry(v.searched)) return timed(std::move(*found));
        if (v.all_unsat && !v.cores.empty()) {
            const run::Stopwatch t0;
            prove::Proof proof = k_.common_proof(v);
            r_.stats.front_seconds += t0.seconds();
            return infeasible(std::move(proof));
        }
        return unknown(v.cores);
    }

    /// Plans and certifies the motion of one design; what it came to.
    Verdict judge(const Design& design) {
        Verdict verdict;
        const run::Stopwatch t0;
        control::MotionFailure failure;
        auto motion = k_.plan(design, &failure);
        if (!motion) {
            r_.stats.verify_seconds += t0.seconds();
            const int dof = k_.dof_of(design);
            if (failure.gave_up) {
                r_.say(run::Stage::Verification, "    motion planning stopped: " + failure.message);
                verdict.gave_up = true;  // the refinement of this guess ends
            } else if (failure.travel) {
                // Nothing along the path to learn from: the next guess may do.
                r_.blocked.no_travel(dof, failure.primitive);
                r_.say(run::Stage::Verification, "    no clear travel: " + failure.message);
            } else {
                r_.blocked.out_of_reach(dof, failure.primitive, failure.transition);
                r_.say(run::Stage::Verification, "    out of reach at " + failure.message);
                verdict.places.push_back(failure.transition
                                             ? PathPlace{failure.primitive, 0.0, true, failure.s}
                                             : PathPlace{failure.primitive, failure.s});
            }
            return verdict;
        }
        verify::Certificate cert = k_.certify(design, *motion);
        for (int pass = 0; pass < s_.motion_refinement_passes && cert.violations.empty() &&
                           !cert.coarse_pairs.empty() && r_.remaining() > 0.0;
             ++pass) {
            if (!k_.refine_motion(design, *motion, cert.coarse_pairs)) break;
            cert = k_.certify(design, *motion);
        }
        r_.stats.verify_seconds += t0.seconds();
        if (cert.ok) {
            r_.say(run::Stage::Verification,
                   text::format("    certified: %s, self margin %.4f m, deviation %.2g m",
                                text::clearance_text(cert.min_clearance).c_str(),
                                cert.min_self_clearance, cert.max_deviation));
            verdict.solution = k_.solution(design, std::move(*motion), std::move(cert));
            return verdict;
        }
        blame(k_.dof_of(design), cert.violations);
        verdict.places = counterexamples(cert.violations);
        if (!cert.violations.empty())
            r_.say(run::Stage::Verification,
                   "    verification: " + std::to_string(cert.violations.size()) +
                       " violation(s), first: " + cert.violations.front().message);
        return verdict;
    }

private:
    /// For each allowed joint count, fewest first, the front stage and
    /// every skeleton it offers, until one is certified. Breadth first:
    /// every skeleton, of every joint count, gets its best initial guess
    /// before any gets its others (retry). A wrong branch fails on each of
    /// its guesses, and each failure costs a full refinement; where every
    /// first guess of fewer joints fails, more joints are usually needed (a
    /// base ringed by posts, scripts/keyhole-tasks).
    std::optional<Solution> first_pass(Verdicts& v) {
        for (int dof : k_.joint_counts()) {
            if (r_.remaining() <= 0.0) {
                v.all_unsat = false;
                break;
            }
            if (k_.ruled_out(dof, v)) continue;
            const run::Stopwatch t0;
            const std::string joints = std::to_string(dof) + " joints";
            r_.say(run::Stage::FrontStage, joints + ": front stage");
            auto front = k_.front_stage(dof);
            const FrontAnswer answer = front->check();
            r_.stats.front_seconds += t0.seconds();
            if (answer == FrontAnswer::Unsat) {
                // A core found for fewer joints often holds here too:
                // checking it is cheaper than minimising afresh.
                auto& cores = v.cores;
                const auto known = std::find_if(cores.begin(), cores.end(),
                                                [&](const auto& c) { return front->conflicts(c); });
                cores.push_back(known != cores.end() ? *known : front->minimal_core());
                const std::string names = task::to_string(cores.back(), ", ");
                r_.say(run::Stage::FrontStage,
                       joints + ": proved infeasible, conflict between " + names);
                r_.tried.push_back(joints + " proved infeasible (" + names + ")");
                continue;
            }
            v.all_unsat = false;
            if (answer == FrontAnswer::Unknown) {
                r_.say(run::Stage::FrontStage,
                       joints + ": front stage gave up (" + front->reason_unknown() + ")");
                r_.tried.push_back(joints + ": front stage undecided");
                continue;
            }
            int skeletons = 0;
            while (auto sk = front->next()) {
                ++skeletons;
                ++r_.stats.skeletons;
                r_.say(run::Stage::Search,
                       text::format("%d joints: skeleton %d (", dof, skeletons) + k_.describe(*sk) +
                           ")");
                v.searched.push_back(*sk);
                if (auto found = try_skeleton(*sk, s_.first_guesses, s_.seed))
                    return shorten(*sk, std::move(*found));
            }
            if (skeletons == 0 && !front->why_none().empty()) {
                r_.say(run::Stage::Search, joints + ": " + front->why_none());
                r_.tried.push_back(joints + ": " + front->why_none());
                continue;
            }
            const bool exhausted = front->exhausted();
            r_.tried.push_back(text::format("%d joints: %d skeleton(s) searched", dof, skeletons) +
                               (exhausted ? " (all of them) without a certified motion" : ""));
            if (exhausted) r_.say(run::Stage::Search, joints + ": search exhausted");
        }
        return std::nullopt;
    }

    // Every skeleton the front stage offered, again and again with initial
    // guesses of other seeds, until one is certified or the time runs out:
    // a skeleton exhausted by blocking is no proof that the task is
    // infeasible. Pass 0 gives each skeleton the other guesses of the
    // search's own seed (its best one was tried already); later passes,
    // further seeds. The seeds follow from the pass, so solutions stay
    // repeatable.
    std::optional<Solution> retry(const std::vector<Skeleton>& skeletons) {
        // However many passes the time allows, the explanation says it once.
        unsigned retries = 0;
        auto note_retries = [&] {
            if (retries > 0)
                r_.tried.push_back(
                    text::format("every skeleton retried %u time(s) with other seeds", retries));
        };
        for (unsigned pass = 0; r_.remaining() > 0.0; ++pass) {
            const unsigned seed = s_.seed + 1000003u * pass;
            for (const Skeleton& sk : skeletons) {
                if (r_.remaining() <= 0.0) break;
                const int dof = k_.dof_of(sk);
                r_.say(run::Stage::Search,
                       pass == 0
                           ? text::format("%d joints: more initial guesses for ", dof) +
                                 k_.describe(sk)
                           : text::format("%d joints: retry %u, ", dof, pass) + k_.describe(sk));
                if (auto found = try_skeleton(sk, s_.retry_guesses, seed)) {
                    note_retries();
                    return shorten(sk, std::move(*found));
                }
            }
            if (pass > 0) ++retries;
        }
        note_retries();
        return std::nullopt;
    }

public:
    /// Up to `count` initial guesses of a skeleton, each refined with every
    /// attempt the kind offers until one is certified. Refinements that
    /// failed before (same skeleton, attempt and start) are not repeated:
    /// the shortening pass and the retries would otherwise redo them.
    /// Without `refine_too` only what the kind certifies without a
    /// refinement is tried.
    std::optional<Solution> try_skeleton(const Skeleton& skeleton, int count, unsigned seed,
                                         bool refine_too = true) {
        const run::Stopwatch started;
        std::vector<Guess> guesses = k_.guesses(skeleton, count, seed, refine_too);
        if (auto s = k_.before_refinement(skeleton, guesses, refine_too, *this)) {
            r_.certified_seconds = started.seconds();
            return s;
        }
        if (!refine_too) return std::nullopt;
        for (std::size_t n = 0; n < guesses.size() && static_cast<int>(n) < count; ++n) {
            const Guess& g = guesses[n];
            if (r_.remaining() <= 0.0) return std::nullopt;
            std::vector<Attempt> attempts = k_.attempts(skeleton, g);
            std::erase_if(attempts, [&](const Attempt& a) {
                return failed_.count(k_.key(skeleton, g, a)) > 0;
            });
            if (attempts.empty()) continue;  // failed before from this very start
            r_.say(run::Stage::Search, "  start: " + k_.describe(g));
            for (std::size_t i = 0; i < attempts.size(); ++i) {
                if (auto s = refine(skeleton, g, attempts[i])) return s;
                failed_.insert(k_.key(skeleton, g, attempts[i]));
                if (i + 1 < attempts.size()) ++r_.stats.fallbacks;
            }
        }
        return std::nullopt;
    }

    /// Seconds the refinement of the last certified design took.
    double certified_seconds() const { return r_.certified_seconds; }

    /// Certified designs of one task, and the choice among them.
    class Shortlist {
    public:
        Shortlist(SearchFlow& flow, Solution first) : flow_(flow) {
            certified_.push_back({std::move(first), flow.r_.stats.certified_by});
            shortest_ = flow.k_.length_of(certified_.front().solution);
        }
        double shortest() const { return shortest_; }
        std::size_t size() const { return certified_.size(); }
        const Solution& first() const { return certified_.front().solution; }
        /// A candidate certified by `by`; false when it is longer than the
        /// shortest by more than a tie (it is then dropped).
        bool offer(Solution s, const std::string& by) {
            const double length = flow_.k_.length_of(s);
            const double tie = flow_.s_.length_tie;
            if (length < shortest_ - 1e-6)
                flow_.r_.say(run::Stage::Shortening,
                             text::format("    shorter: total length %.4f m", length));
            else if (length <= shortest_ + tie)
                flow_.r_.say(run::Stage::Shortening,
                             text::format("    as short, to within %.4f m: total length %.4f m",
                                          tie, length));
            else
                return false;
            shortest_ = std::min(shortest_, length);
            certified_.push_back({std::move(s), by});
            return true;
        }
        /// A twin of the first (the same design, verified with another
        /// branch): kept whatever its length, which is the first's.
        void add_twin(Solution s) { certified_.push_back({std::move(s), certified_.front().by}); }
        /// The shortest, or one as short to within length_tie that passes
        /// farther from the obstacles, or among those the quickest motion
        /// (synth/design_choice.h): the same rule for every kind.
        Solution chosen() {
            std::vector<DesignMerit> merits;
            // Every candidate's motion is timed (a few milliseconds each)
            // when there is a choice.
            for (const Entry& c : certified_) {
                merits.push_back({flow_.k_.length_of(c.solution),
                                  c.solution.certificate.min_clearance,
                                  certified_.size() > 1 ? flow_.motion_seconds(c.solution)
                                                        : std::numeric_limits<double>::infinity()});
                if (certified_.size() > 1)
                    flow_.r_.say(
                        run::Stage::Shortening,
                        text::format("%d joints: ", flow_.k_.dof_of(c.solution)) +
                            flow_.k_.describe_choice(c.solution) +
                            text::format(", total length %.4f m: %.3f s of motion",
                                         merits.back().total_length, merits.back().motion_time));
            }
            Entry& c = certified_[choose_design(merits, flow_.s_.length_tie)];
            flow_.r_.stats.certified_by = c.by;
            return std::move(c.solution);
        }

    private:
        struct Entry {
            Solution solution;
            std::string by;
        };
        SearchFlow& flow_;
        std::vector<Entry> certified_;
        double shortest_ = 0.0;
    };

    /// Whether a variant may still be started: it costs about what the
    /// design found did, and one started too late would leave no time to
    /// time and write the design already certified.
    bool time_for_variant(int dof) {
        const double left = r_.remaining();
        if (left >= s_.shorten_reserve * r_.certified_seconds && left > 0.0) return true;
        r_.say(run::Stage::Shortening,
               text::format("%d joints: no time left to look for a shorter robot", dof));
        return false;
    }

    SearchRun& run_state() { return r_; }

private:
    // The first certified design ends the search of skeletons, but it is
    // often not the shortest: the kind offers variants (other branches,
    // base regions, skeletons of the same joint count), each tried with a
    // fixed amount of work so that solutions stay repeatable.
    Solution shorten(const Skeleton& found, Solution first) {
        Shortlist list(*this, std::move(first));
        k_.shorten(found, list, *this);
        return list.chosen();
    }

    std::optional<Solution> refine(const Skeleton& skeleton, const Guess& start,
                                   const Attempt& attempt) {
        const run::Stopwatch started;
        auto problem = k_.problem(skeleton, start, attempt);
        for (int round = 0; round < s_.refinement_rounds && r_.remaining() > 0.0; ++round) {
            const run::Stopwatch t0;
            std::optional<Design> design = k_.solve(problem, round, start);
            r_.stats.refine_seconds += t0.seconds();
            ++r_.stats.nlp_solves;
            if (!design) {
                r_.blocked.not_converged(k_.dof_of(skeleton));
                return std::nullopt;
            }
            Verdict verdict = judge(*design);
            if (verdict.solution) {
                r_.stats.certified_by = k_.model_name(problem);
                r_.certified_seconds = started.seconds();
                if (r_.stats.first_certified_by.empty())
                    r_.stats.first_certified_by = r_.stats.certified_by;
                return std::move(verdict.solution);
            }
            if (verdict.gave_up) return std::nullopt;
            const int added = k_.learn(problem, verdict, *design);
            if (added < 0) return std::nullopt;  // nothing left to learn
            r_.stats.counterexamples += added;
        }
        return std::nullopt;
    }

    // The chosen design's certified motion, timed for a controller
    // (retime.h): its q stay as certified, so the certificate holds for the
    // result.
    Solution timed(Solution solution) {
        const run::Stopwatch t0;
        control::RetimeStats timing;
        solution.samples = control::retime_for(
            k_.task(), std::move(solution.samples),
            control::joint_limits_for(k_.task(), k_.dof_of(solution)), k_.retime(), &timing);
        r_.say(run::Stage::Timing,
               text::format("timed: %.3f s of motion, %d rests, %d passes, in %.1f ms",
                            timing.duration, timing.rests, timing.passes, 1e3 * t0.seconds()));
        r_.stats.timing = std::move(timing);
        return solution;
    }

    // s the certified motion of a candidate takes, timed as the one
    // returned will be.
    double motion_seconds(const Solution& solution) const {
        control::RetimeStats timing;
        control::retime_for(k_.task(), solution.samples,
                            control::joint_limits_for(k_.task(), k_.dof_of(solution)), k_.retime(),
                            &timing);
        return timing.duration;
    }

    Solution infeasible(prove::Proof proof) const {
        Solution out;
        out.task_name = k_.task().name;
        out.status = Status::Kind::Infeasible;
        out.explanation.message = "Proved infeasible: " + proof.message;
        out.explanation.core = std::move(proof.core);
        out.explanation.separation = std::move(proof.separation);
        out.explanation.geodesic = std::move(proof.geodesic);
        out.explanation.enclosure = std::move(proof.enclosure);
        return out;
    }

    // No design and no proof: what was tried, and the cores of the joint
    // counts the front stage proved infeasible.
    Solution unknown(const std::vector<std::vector<task::TaskPart>>& cores) const {
        Solution out;
        out.task_name = k_.task().name;
        const bool out_of_time = r_.remaining() <= 0.0;
        out.status = Status(
            Status::Kind::Unknown, r_.stage,
            out_of_time ? "time limit" : "every joint count tried without a certified robot");
        std::string tried;
        for (std::size_t i = 0; i < r_.tried.size(); ++i) tried += (i ? "; " : "") + r_.tried[i];
        out.explanation.message =
            "No certified robot found" + std::string(out_of_time ? " within the time limit" : "") +
            (r_.tried.empty() ? std::string(": the time ran out before any robot was tried.")
                              : ": " + tried + ".") +
            (r_.blocked.empty()
                 ? std::string()
                 : " What stopped the candidates: " + r_.blocked.describe(k_.task()) + ".");
        for (const auto& c : cores)
            for (const auto& part : c)
                if (std::find(out.explanation.core.begin(), out.explanation.core.end(), part) ==
                    out.explanation.core.end())
                    out.explanation.core.push_back(part);
        return out;
    }

    // Each obstacle (and the tool against the links) once per candidate.
    void blame(int dof, const std::vector<verify::Violation>& violations) {
        std::set<int> blamed;
        for (const auto& v : violations) {
            if (v.kind == verify::Violation::Kind::Clearance && blamed.insert(v.obstacle).second)
                r_.blocked.obstacle(dof, v.obstacle, v.link, v.primitive);
            if (v.kind == verify::Violation::Kind::SelfCollision && blamed.insert(-1).second)
                r_.blocked.self_collision(dof, v.primitive);
            if (v.kind == verify::Violation::Kind::ToolAxis && blamed.insert(-2).second)
                r_.blocked.tool_axis(dof, v.primitive);
        }
    }

    // Where the refinement must look next: the violations along the path,
    // one per millimetre of a primitive, at most counterexamples_per_round
    // of them; every violation in a transition (a kind may count them).
    std::vector<PathPlace> counterexamples(const std::vector<verify::Violation>& violations) const {
        std::vector<PathPlace> places;
        std::set<std::pair<int, long>> seen;
        int along = 0;
        for (const auto& v : violations) {
            if (v.primitive < 0 || v.travel) continue;
            if (v.transition) {
                places.push_back({v.primitive, 0.0, true, v.s});
                continue;
            }
            if (!seen.insert({v.primitive, std::lround(v.s * 1e3)}).second) continue;
            places.push_back({v.primitive, v.s});
            if (++along >= s_.counterexamples_per_round) break;
        }
        return places;
    }

    Kind& k_;
    SearchRun& r_;
    const SearchSettings s_;
    /// Refinements that failed, by the kind's key (skeleton, attempt,
    /// start): a refinement is a function of these.
    std::set<std::vector<double>> failed_;
};

}  // namespace modsynth::synth
