#pragma once
// What stopped the candidate robots of a search, by joint count and by the
// task part to blame: an "unknown" answer says which obstacle or which
// stretch of the path to change, not only how often it tried.
#include <functional>
#include <map>
#include <string>

#include <modsynth/task/strokes.h>

namespace modsynth::synth {

class Blockers {
public:
    /// A candidate of `dof` joints had link `link` (0-based) too near
    /// `obstacle` at `primitive`.
    void obstacle(int dof, int obstacle, int link, int primitive);
    void self_collision(int dof, int primitive);
    /// No pose reached a point of `primitive`, or (transition) the
    /// transition after it.
    void out_of_reach(int dof, int primitive, bool transition);
    /// No clear travel from the stroke that `primitive` ends.
    void no_travel(int dof, int primitive);
    void not_converged(int dof);

    bool empty() const { return by_dof_.empty(); }
    /// "with 3 joints: obstacles[0] in the way of link 2 (14 candidates, at
    /// trajectory[3] to trajectory[40]), out of reach at the transitions
    /// (3, after trajectory[11])": per joint count, the four blockers met
    /// most often.
    template <task::StrokedTask Task>
    std::string describe(const Task& task) const {
        return describe_with([&](int j) { return task::part_name(task, j); });
    }
    /// The same, with `name(j)` naming primitive j of the task.
    std::string describe_with(const std::function<std::string(int)>& name) const;

private:
    enum class Kind { Obstacle, SelfCollision, Reach, TransitionReach, Travel, Refinement };
    struct Tally {
        int count = 0;
        int first = -1;  ///< the primitives where it happened, first and last
        int last = -1;
        unsigned links = 0;  ///< bit k: link k (obstacles)
    };
    Tally& tally(int dof, Kind kind, int index, int primitive);

    std::map<int, std::map<std::pair<Kind, int>, Tally>> by_dof_;
};

}  // namespace modsynth::synth
