// The spatial kind of the search (search_flow.h): DH chains in space. Its
// proofs are prove::spatial_provers, its front stage smt::SpatialFrontStage
// with each arm family's pattern (arms/family.h), its arms those families,
// its refinement nlp/spatial_formulation.h, its motion
// control::plan_spatial_motion and its certificate the spatial verifier.
#include <modsynth/synth/spatial_synthesizer.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>

#include <modsynth/arms/pointing.h>
#include <modsynth/control/joint_limits.h>
#include <modsynth/geometry/primitive3.h>
#include <modsynth/nlp/solver.h>
#include <modsynth/prove/provers.h>
#include <modsynth/run/deadline.h>
#include <modsynth/run/stopwatch.h>
#include <modsynth/task/part.h>
#include <modsynth/task/spatial_strokes.h>
#include <modsynth/text/format.h>
#include <modsynth/text/option_check.h>
#include <modsynth/verify/spatial_verifier.h>

#include "search_flow.h"

namespace modsynth::synth {
namespace {

using geometry::Vec3;
using run::Stage;

void add_point(std::vector<nlp::SpatialPoint>& pts, const nlp::SpatialPoint& p) {
    for (const auto& q : pts)
        if (q.primitive == p.primitive && q.transition == p.transition &&
            std::abs(q.s - p.s) < 1e-4 && std::abs(q.t - p.t) < 1e-4)
            return;
    pts.push_back(p);
}

/// A skeleton of the front stage with the initial guesses of the search's
/// own seed that ordered it among the others.
struct SkeletonEntry {
    arms::Skeleton skeleton;
    std::vector<ScoredDesign> first;
};

/// The spatial front stage: every skeleton the pattern allows, in the order
/// of its best initial guess (clear ones shortest first, then by margin).
class SpatialFront : public FrontStageRun<SkeletonEntry> {
public:
    /// The skeletons listed go to `entries` too, where the kind finds the
    /// variants of a design while shortening.
    SpatialFront(const task::SpatialTask& task, int dof, const smt::SpatialFrontStageOptions& fo,
                 const SpatialSynthesisOptions& options, SearchRun& run,
                 std::vector<SkeletonEntry>& entries)
        : front_(task, dof, fo),
          task_(task),
          dof_(dof),
          opt_(options),
          run_(run),
          entries_(entries) {
        entries_.clear();
    }

    FrontAnswer check() override {
        switch (front_.check()) {
            case smt::SpatialFrontStage::Result::Sat:
                return FrontAnswer::Sat;
            case smt::SpatialFrontStage::Result::Unsat:
                return FrontAnswer::Unsat;
            case smt::SpatialFrontStage::Result::Unknown:
                return FrontAnswer::Unknown;
        }
        return FrontAnswer::Unknown;
    }
    std::vector<task::TaskPart> minimal_core() override { return front_.minimal_core(); }
    bool conflicts(const std::vector<task::TaskPart>& parts) override {
        return front_.conflicts(parts);
    }
    std::string reason_unknown() const override { return front_.reason_unknown(); }
    std::optional<SkeletonEntry> next() override {
        if (!listed_) list();
        if (at_ >= entries_.size() || run_.remaining() <= 0.0) return std::nullopt;
        return entries_[at_++];
    }
    bool exhausted() const override { return listed_ && at_ >= entries_.size(); }
    std::string why_none() const override { return why_none_; }

private:
    // Every family's skeletons whose pattern holds: its variants, with
    // each base region, in the families' order.
    std::vector<arms::Skeleton> skeletons() {
        std::vector<arms::Skeleton> out;
        std::string needs;
        const int regions =
            task_.base_regions.empty() ? 1 : static_cast<int>(task_.base_regions.size());
        for (const arms::Family* family : arms::families()) {
            const std::vector<int> variants = family->variants(dof_, task_.robot);
            if (variants.empty()) {
                needs += (needs.empty() ? "" : "; ") + std::string(family->needs());
                continue;
            }
            for (int variant : variants) {
                const arms::PatternContext context{task_,
                                                   dof_,
                                                   variant,
                                                   front_.sampled_points(),
                                                   opt_.front.slack,
                                                   opt_.margins.pose(),
                                                   opt_.margins.tool_share};
                const smt::Pattern pattern = family->pattern(context);
                for (int r = 0; r < regions; ++r) {
                    const int region = task_.base_regions.empty() ? -1 : r;
                    if (run_.remaining() <= 0.0) return out;
                    if (front_.pattern_holds(pattern, region))
                        out.push_back({family, dof_, variant, region});
                }
            }
        }
        if (out.empty())
            why_none_ = needs.size() == 0
                            ? std::string(
                                  "no arm family's conditions hold (reach, the path off "
                                  "their axes)")
                            : "no arm family fits robot.twists (" + needs + ")";
        return out;
    }

    void list() {
        listed_ = true;
        const run::Stopwatch t0;
        const std::vector<arms::Skeleton> listed = skeletons();
        run_.stats.front_seconds += t0.seconds();
        run_.say(Stage::FrontStage, text::format("%d joints: %zu skeleton(s) (%.3f s)", dof_,
                                                 listed.size(), t0.seconds()));
        for (const auto& sk : listed) {
            if (run_.remaining() <= 0.0) break;
            SkeletonEntry e{sk, spatial_initial_guesses(task_, sk, opt_.first_guesses, opt_.seed,
                                                        opt_.margins, run_.deadline, opt_.guesses)};
            if (!e.first.empty()) entries_.push_back(std::move(e));
        }
        std::stable_sort(entries_.begin(), entries_.end(),
                         [](const SkeletonEntry& a, const SkeletonEntry& b) {
                             const auto& x = a.first.front();
                             const auto& y = b.first.front();
                             const bool cx = x.margin >= 0.0, cy = y.margin >= 0.0;
                             if (cx != cy) return cx;
                             if (cx) return chain_length(x.design) < chain_length(y.design);
                             return x.margin > y.margin;
                         });
    }

    smt::SpatialFrontStage front_;
    const task::SpatialTask& task_;
    int dof_;
    const SpatialSynthesisOptions& opt_;
    SearchRun& run_;
    bool listed_ = false;
    std::vector<SkeletonEntry>& entries_;
    std::size_t at_ = 0;
    std::string why_none_;
};

/// The only way a spatial guess is refined.
struct SpatialAttempt {};

class SpatialKind {
public:
    using Task = task::SpatialTask;
    using Skeleton = SkeletonEntry;
    using Design = kinematics::ArmDesign;
    using Guess = ScoredDesign;
    using Attempt = SpatialAttempt;
    using Problem = nlp::SpatialProblem;

    SpatialKind(const task::SpatialTask& task, const SpatialSynthesisOptions& options,
                SearchRun& run)
        : task_(task), opt_(options), run_(run), verify_(verify_options_for(task, options)) {
        motion_ = opt_.motion;
        motion_.deadline = run.deadline;
    }

    const task::SpatialTask& task() const { return task_; }
    const control::RetimeOptions& retime() const { return opt_.retime; }
    SearchSettings settings() const {
        return {opt_.seed,
                opt_.first_guesses,
                opt_.later_guesses,
                opt_.first_guesses,
                opt_.refinement_rounds,
                opt_.motion_refinement_passes,
                opt_.counterexamples_per_round,
                opt_.length_tie,
                2.0};
    }

    std::optional<prove::Proof> prove() {
        const run::Stopwatch t0;
        auto found = prove::first_proof(prove::spatial_provers(), task_, run_.deadline);
        run_.stats.front_seconds += t0.seconds();
        if (!found) return std::nullopt;
        run_.say(Stage::Proofs,
                 std::string(found->first) + ": proved infeasible, " + found->second.message);
        return std::move(found->second);
    }

    std::vector<int> joint_counts() const {
        std::vector<int> dofs = task_.robot.dof;
        std::sort(dofs.begin(), dofs.end());
        return dofs;
    }

    bool ruled_out(int, Verdicts<Skeleton>&) { return false; }

    std::unique_ptr<FrontStageRun<Skeleton>> front_stage(int dof) {
        smt::SpatialFrontStageOptions fo = opt_.front;
        fo.time_limit = std::min(fo.time_limit, std::max(0.05, run_.remaining()));
        fo.deadline = run_.deadline;
        return std::make_unique<SpatialFront>(task_, dof, fo, opt_, run_, listed_[dof]);
    }

    void prune_retries(Verdicts<Skeleton>&) {}

    // A core shared by every joint count (or the union of theirs).
    prove::Proof common_proof(const Verdicts<Skeleton>& verdicts) {
        prove::Proof proof;
        for (const auto& c : verdicts.cores)
            for (const auto& part : c)
                if (std::find(proof.core.begin(), proof.core.end(), part) == proof.core.end())
                    proof.core.push_back(part);
        std::string tried;
        for (std::size_t i = 0; i < run_.tried.size(); ++i)
            tried += (i ? "; " : "") + run_.tried[i];
        proof.message = "no chain of " +
                        std::string(task_.robot.dof.size() > 1 ? "any allowed joint count"
                                                               : "the allowed joint count") +
                        " meets the conditions every chain must meet: " + tried + ".";
        return proof;
    }

    std::vector<Guess> guesses(const Skeleton& sk, int count, unsigned seed, bool) {
        if (seed == opt_.seed && count <= static_cast<int>(sk.first.size())) return sk.first;
        return spatial_initial_guesses(task_, sk.skeleton, count, seed, opt_.margins, run_.deadline,
                                       opt_.guesses);
    }

    template <class Flow>
    std::optional<Solution> before_refinement(const Skeleton&, std::vector<Guess>&, bool, Flow&) {
        return std::nullopt;
    }

    std::vector<Attempt> attempts(const Skeleton&, const Guess&) const { return {Attempt{}}; }

    std::vector<double> key(const Skeleton& sk, const Guess& g, const Attempt&) const {
        const auto& s = sk.skeleton;
        const auto& families = arms::families();
        const auto family =
            std::find(families.begin(), families.end(), s.family) - families.begin();
        const auto& shape = g.design.shape;
        std::vector<double> key{static_cast<double>(family),
                                static_cast<double>(s.dof),
                                static_cast<double>(s.variant),
                                static_cast<double>(s.base_region),
                                shape.base.x(),
                                shape.base.y(),
                                shape.base.z()};
        key.insert(key.end(), shape.values.begin(), shape.values.end());
        return key;
    }

    Problem problem(const Skeleton& sk, const Guess& g, const Attempt&) const {
        const arms::Skeleton& s = sk.skeleton;
        nlp::SpatialProblem p;
        p.task = &task_;
        p.start = g.design;
        for (const arms::Bound& b : s.family->value_bounds(task_.robot, s.dof, s.variant))
            p.family.values.push_back({b.lower, b.upper});
        const arms::Bound along = s.family->along_bound(s.dof);
        p.family.along = {along.lower, along.upper};
        p.family.length_weights = s.family->length_weights(s.dof, s.variant);
        p.family.rows = s.family->design_rows(task_, s.dof, s.variant);
        const auto pins = arms::along_pins(*s.family, task_, s.dof, s.variant);
        arms::pin_along(pins, task_, p.start.along);
        for (const auto& slots : pins) {
            p.family.fixed_along.emplace_back();
            for (const auto& v : slots) p.family.fixed_along.back().push_back(v.has_value());
        }
        if (sk.skeleton.base_region >= 0)
            p.base_box = task_.base_regions[static_cast<std::size_t>(sk.skeleton.base_region)];
        p.margins = opt_.margins;
        p.points = initial_points(g.design);
        return p;
    }

    // One round of the reduced program; a clear start that the first
    // round could not improve may still be certified as it is.
    std::optional<Design> solve(Problem& p, int round, const Guess& start) {
        const run::Stopwatch t0;
        const nlp::SpatialFormulation f(p);
        nlp::SolverOptions so;
        so.time_limit = std::min(opt_.solve_seconds, std::max(0.05, run_.remaining()));
        so.deadline = run_.deadline.at_least(0.05);
        so.max_iterations = opt_.solve_iterations;
        const nlp::SolverResult res = nlp::minimize(f, so);
        if (!res.usable()) {
            run_.say(Stage::Refinement,
                     text::format("    refinement did not converge in %d iterations, %.3f s (",
                                  res.iterations, t0.seconds()) +
                         res.message + ")");
            if (round > 0 || start.margin < 0.0) return std::nullopt;
            return p.start;
        }
        Design design = f.design(res.x);
        run_.say(Stage::Refinement,
                 text::format("    refined: %s with %zu points, %d constraints, in %d iterations, "
                              "%.3f s",
                              describe_design(design).c_str(), p.points.size(), f.num_constraints(),
                              res.iterations, t0.seconds()));
        return design;
    }

    int learn(Problem& p, const Verdict& verdict, const Design& design) const {
        const std::size_t before = p.points.size();
        for (const PathPlace& place : verdict.places) {
            const double length =
                geometry::length(task_.trajectory[static_cast<std::size_t>(place.primitive)]);
            add_point(p.points, place.transition
                                    ? nlp::SpatialPoint{place.primitive, length, true, place.t}
                                    : nlp::SpatialPoint{place.primitive, place.s});
        }
        if (p.points.size() == before) return -1;
        p.start = design;
        return static_cast<int>(p.points.size() - before);
    }

    std::string model_name(const Problem&) const { return "spatial"; }

    std::optional<std::vector<control::Sample>> plan(const Design& design,
                                                     control::MotionFailure* failure) const {
        return control::plan_spatial_motion(task_, design, motion_, failure);
    }
    verify::Certificate certify(const Design& design,
                                const std::vector<control::Sample>& samples) const {
        return verify::certify(task_, design.chain(), samples, verify_);
    }
    bool refine_motion(const Design& design, std::vector<control::Sample>& samples,
                       const std::vector<int>& pairs) const {
        return control::refine_spatial_motion(task_, design, samples, pairs);
    }
    Solution solution(const Design& design, std::vector<control::Sample> samples,
                      verify::Certificate cert) const {
        Solution s;
        s.task_name = task_.name;
        s.status = Status::Solved;
        s.dh_robot = design.chain();
        s.samples = std::move(samples);
        s.certificate = std::move(cert);
        return s;
    }

    // Another skeleton (a hanging column, another base region) may give a
    // shorter chain: the next few skeletons of the same joint count, in the
    // front stage's order, get one refinement each.
    template <class Flow>
    void shorten(const Skeleton& found, typename Flow::Shortlist& list, Flow& flow) {
        const std::vector<Skeleton>& listed = listed_[found.skeleton.dof];
        const auto same = [&](const Skeleton& sk) {
            return sk.skeleton.family == found.skeleton.family &&
                   sk.skeleton.variant == found.skeleton.variant &&
                   sk.skeleton.base_region == found.skeleton.base_region;
        };
        const auto at = std::find_if(listed.begin(), listed.end(), same);
        int variants = 0;
        for (auto it = at == listed.end() ? listed.end() : at + 1; it != listed.end(); ++it) {
            const Skeleton& sk = *it;
            if (variants >= opt_.shortening_variants) break;
            if (!flow.time_for_variant(found.skeleton.dof)) return;
            ++variants;
            run_.say(Stage::Shortening, describe(sk) + ": a shorter design?");
            if (auto s = flow.try_skeleton(sk, 1, opt_.seed))
                list.offer(std::move(*s), run_.stats.certified_by);
        }
    }

    std::string describe(const Skeleton& sk) const {
        const auto& s = sk.skeleton;
        return std::string(s.family->name()) + ", " + s.family->describe_variant(s.variant) +
               text::format(", base region %d", s.base_region);
    }
    std::string describe(const Guess& g) const {
        return describe_design(g.design) + text::format(", margin %.4f m", g.margin);
    }
    std::string describe_choice(const Solution& s) const {
        return text::format("chain %.4f m", s.dh_robot->total_length());
    }
    int dof_of(const Skeleton& sk) const { return sk.skeleton.dof; }
    int dof_of(const Design& d) const { return d.dof(); }
    int dof_of(const Solution& s) const { return s.dh_robot->dof(); }
    double length_of(const Solution& s) const { return s.dh_robot->total_length(); }

private:
    static std::string describe_design(const Design& d) {
        return static_cast<const arms::Family*>(d.model)->describe(d);
    }

    std::vector<nlp::SpatialPoint> initial_points(const kinematics::ArmDesign& design) const {
        double total = 0.0;
        for (const auto& p : task_.trajectory) total += geometry::length(p);
        const double spacing = std::max(opt_.point_spacing, total / std::max(1, opt_.max_points));
        std::vector<nlp::SpatialPoint> pts;
        const arms::Family& family = *static_cast<const arms::Family*>(design.model);
        const Vec3 shoulder = family.reach_centre(design);
        const bool sweeps = family.along_count(design.dof(), design.shape.variant) > 0;
        for (int j = 0; j < static_cast<int>(task_.trajectory.size()); ++j) {
            const auto& prim = task_.trajectory[static_cast<std::size_t>(j)];
            const double len = geometry::length(prim);
            const int n = std::max(2, static_cast<int>(std::ceil(len / spacing)));
            for (int i = 0; i <= n; ++i) pts.push_back({j, len * i / n});
            // Where the elbow stretches and folds most.
            add_point(pts, {j, geometry::nearest(prim, shoulder).s});
            add_point(pts, {j, geometry::farthest(prim, shoulder).s});
            if (sweeps && task::has_transition_after(task_, j))
                for (double t : {0.25, 0.5, 0.75}) pts.push_back({j, len, true, t});
        }
        return pts;
    }

    const task::SpatialTask& task_;
    const SpatialSynthesisOptions& opt_;
    SearchRun& run_;
    control::SpatialMotionOptions motion_;
    verify::VerifyOptions verify_;
    /// By joint count: the skeletons its front stage listed, in order.
    std::map<int, std::vector<Skeleton>> listed_;
};

static_assert(SearchKind<SpatialKind>);

}  // namespace

bool SpatialSynthesisOptions::IsValid(std::string* error) const {
    return text::OptionCheck("SpatialSynthesisOptions", error)
        .at_least("time_limit", time_limit, 0.0)
        .nested("motion", motion)
        .nested("retime", retime)
        .nested("verify", verify)
        .nested("front", front)
        .nested("guesses", guesses)
        .greater("point_spacing", point_spacing, 0.0)
        .at_least("max_points", max_points, 2)
        .at_least("first_guesses", first_guesses, 1)
        .at_least("later_guesses", later_guesses, 1)
        .at_least("refinement_rounds", refinement_rounds, 1)
        .greater("solve_seconds", solve_seconds, 0.0)
        .at_least("solve_iterations", solve_iterations, 1)
        .at_least("motion_refinement_passes", motion_refinement_passes, 0)
        .at_least("counterexamples_per_round", counterexamples_per_round, 1)
        .at_least("shortening_variants", shortening_variants, 0)
        .at_least("length_tie", length_tie, 0.0)
        .ok();
}

verify::VerifyOptions verify_options_for(const task::SpatialTask&,
                                         const SpatialSynthesisOptions& options) {
    verify::VerifyOptions v = options.verify;
    v.max_joint_step = options.motion.max_joint_step;
    v.max_ee_step = std::max(v.max_ee_step, options.motion.max_ee_step);
    return v;
}

Solution synthesize(const task::SpatialTask& task, const SpatialSynthesisOptions& options,
                    SynthesisStats* stats) {
    text::require_valid(options);
    SynthesisStats local;
    SearchRun run(run::Deadline::in(std::max(0.0, options.time_limit)).cancelled_by(options.cancel),
                  options.progress, stats ? *stats : local);
    SpatialKind kind(task, options, run);
    return SearchFlow<SpatialKind>(kind, run).run();
}

}  // namespace modsynth::synth
