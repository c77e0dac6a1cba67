#pragma once
// Which model of the swept area the refinement starts from (paper III-B,
// III-D, or separating lines at sampled points), and in what order the
// models are tried for one initial guess. Every model's candidate goes to
// the same certified verification; one that fails it is a failed attempt,
// and the next model is tried.
#include <optional>
#include <string>
#include <vector>

#include <modsynth/kinematics/robot.h>
#include <modsynth/nlp/formulation.h>
#include <modsynth/smt/skeleton.h>
#include <modsynth/task/task.h>

namespace modsynth::synth {

enum class SweptChoice {
    /// SV^over (sampled points kept) first for two joints where it can
    /// hold, then separating lines.
    Auto,
    /// The paper's SV^app (III-D) at the paper's points, then lines.
    App,
    /// The paper's SV^over (III-B) at the paper's points, then lines.
    Over,
    /// Separating lines at sampled points only.
    Lines,
};

const char* to_string(SweptChoice choice);
/// "auto", "app", "over" or "lines"; nullopt otherwise.
std::optional<SweptChoice> swept_choice_from(const std::string& name);

/// One refinement of an initial guess: the model of its first round (later
/// rounds, after a verification failure, use lines with the counterexamples).
struct SweptAttempt {
    nlp::SweptVolume swept = nlp::SweptVolume::Sampled;
    /// The paper's points (ends, closest and farthest of each primitive)
    /// and the swept volume alone against obstacles while tracing.
    bool paper = false;
};

const char* name_of(const SweptAttempt& attempt);

/// The attempts for one initial guess, in order.
std::vector<SweptAttempt> swept_attempts(SweptChoice choice, const task::Task& task,
                                         const smt::Skeleton& skeleton,
                                         const kinematics::Robot& guess);

/// Whether SV^over could hold near this robot: no obstacle centre inside
/// conv(disc(o_j, r_a) and primitive j) for any primitive j, o_j the point
/// the distal pair turns about. When one is, the over-approximation cannot
/// be met nearby and the attempt would only cost time.
bool swept_over_plausible(const task::Task& task, const kinematics::Robot& robot);

}  // namespace modsynth::synth
