#pragma once
// What the one search (search_flow.h) asks of a kind of task, plane or
// space, and the values its steps hand each other.
#include <concepts>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <modsynth/control/motion.h>
#include <modsynth/control/retime.h>
#include <modsynth/prove/proof.h>
#include <modsynth/run/deadline.h>
#include <modsynth/run/progress.h>
#include <modsynth/run/stopwatch.h>
#include <modsynth/synth/blockers.h>
#include <modsynth/synth/solution.h>
#include <modsynth/synth/synthesizer.h>
#include <modsynth/task/part.h>
#include <modsynth/verify/verifier.h>

namespace modsynth::synth {

/// Where a candidate failed along the path: arc length s of primitive j
/// (index in the task's trajectory), or in the transition after j at t (the
/// kind's measure of progress through it).
struct PathPlace {
    int primitive = 0;
    double s = 0.0;
    bool transition = false;
    double t = 0.0;
};

/// What planning and certifying one candidate came to: a certified answer,
/// or where the next refinement must look (counterexample-guided).
struct Verdict {
    std::optional<Solution> solution;
    /// Motion planning gave up (a deadline, a cap): nothing was learnt.
    bool gave_up = false;
    std::vector<PathPlace> places;
};

/// What the front stages concluded, joint count by joint count.
template <class Skeleton>
struct Verdicts {
    /// The cores of the joint counts proved infeasible.
    std::vector<std::vector<task::TaskPart>> cores;
    /// In words, proofs of joint counts the front stage cannot check (a
    /// loop round an obstacle, for 2 planar joints); their cores are in
    /// `cores` too.
    std::vector<std::string> own_proofs;
    std::vector<Skeleton> searched;  ///< every skeleton tried, for the retries
    bool all_unsat = true;           ///< every joint count proved infeasible
};

enum class FrontAnswer { Sat, Unsat, Unknown };

/// One joint count's front stage, as the search uses it.
template <class Skeleton>
class FrontStageRun {
public:
    virtual ~FrontStageRun() = default;
    /// The relaxation for any design of the joint count: Unsat is a proof.
    virtual FrontAnswer check() = 0;
    /// After Unsat: the conflicting parts, minimal when time allows.
    virtual std::vector<task::TaskPart> minimal_core() = 0;
    /// Whether these parts alone are proved to conflict.
    virtual bool conflicts(const std::vector<task::TaskPart>& parts) = 0;
    virtual std::string reason_unknown() const = 0;
    /// After Sat: the skeletons, best first, one at a time (nothing once
    /// none is left or the time is up).
    virtual std::optional<Skeleton> next() = 0;
    /// Whether next() ran out of skeletons (not of time).
    virtual bool exhausted() const = 0;
    /// Why a satisfiable relaxation gave no skeleton at all, when it did
    /// not (empty otherwise).
    virtual std::string why_none() const { return {}; }
};

/// The search's own numbers, whatever the kind.
struct SearchSettings {
    unsigned seed = 0;
    int first_guesses = 1;       ///< per skeleton in the first pass
    int retry_guesses = 4;       ///< per skeleton in each later pass
    int variant_guesses = 1;     ///< per variant while shortening
    int refinement_rounds = 12;  ///< per initial guess and attempt
    int motion_refinement_passes = 8;
    int counterexamples_per_round = 24;
    double length_tie = 5e-4;
    double shorten_reserve = 2.0;
};

/// The state every step of one search shares.
struct SearchRun {
    SearchRun(const run::Deadline& deadline, const run::ProgressSink& progress,
              SynthesisStats& stats)
        : deadline(deadline), progress(progress), stats(stats) {}

    double remaining() const { return deadline.remaining(); }
    void say(run::Stage where, const std::string& message) {
        stage = message;
        if (progress) progress({where, message, clock.seconds()});
    }

    const run::Stopwatch clock;
    const run::Deadline deadline;
    run::ProgressSink progress;
    SynthesisStats& stats;
    std::vector<std::string> tried;
    std::string stage = "before the front stage";  ///< the last said, for an unknown answer
    Blockers blocked;  ///< what stopped the candidates, for an unknown answer
    /// Seconds the refinement of the last certified design took.
    double certified_seconds = 0.0;
};

/// A kind of task for SearchFlow: its types and its steps. Each step is
/// the kind's geometry; the order of the steps and every choice between
/// them belong to the flow.
template <class K>
concept SearchKind = requires(K& k, const K& ck, const typename K::Skeleton& sk,
                              const typename K::Guess& g, const typename K::Attempt& a,
                              typename K::Problem& p, const typename K::Design& d,
                              std::vector<control::Sample>& samples, const Solution& solution,
                              Verdicts<typename K::Skeleton>& v, const Verdict& verdict) {
    typename K::Task;
    typename K::Skeleton;  ///< the front stage's discrete choices
    typename K::Design;    ///< a candidate robot
    typename K::Guess;     ///< an initial guess: a design and its score
    typename K::Attempt;   ///< a way of refining a guess
    typename K::Problem;   ///< one refinement's program, grown round by round
    { ck.task() } -> std::convertible_to<const typename K::Task&>;
    { ck.settings() } -> std::convertible_to<SearchSettings>;
    { ck.retime() } -> std::convertible_to<const control::RetimeOptions&>;
    // Proofs and the front stage.
    { k.prove() } -> std::same_as<std::optional<prove::Proof>>;
    { ck.joint_counts() } -> std::same_as<std::vector<int>>;
    { k.ruled_out(0, v) } -> std::same_as<bool>;
    { k.front_stage(0) } -> std::same_as<std::unique_ptr<FrontStageRun<typename K::Skeleton>>>;
    {k.prune_retries(v)};
    { k.common_proof(v) } -> std::same_as<prove::Proof>;
    // Guesses and refinement.
    { k.guesses(sk, 0, 0u, true) } -> std::same_as<std::vector<typename K::Guess>>;
    { k.attempts(sk, g) } -> std::same_as<std::vector<typename K::Attempt>>;
    { ck.key(sk, g, a) } -> std::same_as<std::vector<double>>;
    { k.problem(sk, g, a) } -> std::same_as<typename K::Problem>;
    { k.solve(p, 0, g) } -> std::same_as<std::optional<typename K::Design>>;
    { k.learn(p, verdict, d) } -> std::same_as<int>;
    { ck.model_name(p) } -> std::convertible_to<std::string>;
    // Motion and certificate.
    {
        k.plan(d, static_cast<control::MotionFailure*>(nullptr))
        } -> std::same_as<std::optional<std::vector<control::Sample>>>;
    { ck.certify(d, samples) } -> std::same_as<verify::Certificate>;
    { ck.refine_motion(d, samples, std::vector<int>{}) } -> std::same_as<bool>;
    {
        ck.solution(d, std::vector<control::Sample>{}, verify::Certificate{})
        } -> std::same_as<Solution>;
    // Words and figures.
    { ck.describe(sk) } -> std::convertible_to<std::string>;
    { ck.describe(g) } -> std::convertible_to<std::string>;
    { ck.describe_choice(solution) } -> std::convertible_to<std::string>;
    { ck.dof_of(sk) } -> std::same_as<int>;
    { ck.dof_of(d) } -> std::same_as<int>;
    { ck.dof_of(solution) } -> std::same_as<int>;
    { ck.length_of(solution) } -> std::same_as<double>;
};

}  // namespace modsynth::synth
