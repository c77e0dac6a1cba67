#include <modsynth/control/travel.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/goals/GoalStates.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/PathSimplifier.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <modsynth/geometry/vec.h>
#include <modsynth/kinematics/motion_clearance.h>
#include <modsynth/kinematics/pose_clearance.h>
#include <modsynth/text/option_check.h>

namespace modsynth::control {
namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;
using Pose = std::vector<double>;

double largest_change(const Pose& a, const Pose& b) {
    double m = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) m = std::max(m, std::abs(b[k] - a[k]));
    return m;
}

Pose between(const Pose& a, const Pose& b, double u) {
    Pose q(a.size());
    for (std::size_t k = 0; k < a.size(); ++k) q[k] = a[k] + u * (b[k] - a[k]);
    return q;
}

class Planner {
public:
    Planner(const task::Task& task, const kinematics::Robot& robot, const TravelOptions& options)
        : task_(task), robot_(robot), opt_(options) {}

    bool clear(const Pose& q, double spare) const {
        return kinematics::pose_clearance(task_.obstacles, robot_, q).worst() >= spare;
    }

    // Appends the poses after a up to b: steps of at most max_joint_step,
    // each pair halved until the certified bound holds. False when it
    // cannot be certified.
    bool append_line(const Pose& a, const Pose& b, std::vector<Pose>& out) const {
        const int pieces = std::max(
            1, static_cast<int>(std::ceil(largest_change(a, b) / opt_.max_joint_step - 1e-9)));
        Pose prev = a;
        for (int i = 1; i <= pieces; ++i) {
            Pose next = i == pieces ? b : between(a, b, static_cast<double>(i) / pieces);
            if (!append_piece(prev, next, opt_.max_halvings, out)) return false;
            prev = std::move(next);
        }
        return true;
    }

    // The other unwrappings of `to`: each joint the short or the long way.
    std::vector<Pose> goals(const Pose& from, const Pose& to) const {
        const std::size_t n = to.size();
        std::vector<Pose> out;
        for (unsigned mask = 0; mask < (1u << n); ++mask) {
            Pose g = to;
            for (std::size_t k = 0; k < n; ++k)
                if (mask & (1u << k)) g[k] -= (to[k] >= from[k] ? 1.0 : -1.0) * geometry::kTau;
            out.push_back(std::move(g));
        }
        // Shortest first: by the largest joint change, then the total.
        auto cost = [&](const Pose& g) {
            double sum = 0.0;
            for (std::size_t k = 0; k < n; ++k) sum += std::abs(g[k] - from[k]);
            return std::pair{largest_change(from, g), sum};
        };
        std::stable_sort(out.begin(), out.end(),
                         [&](const Pose& a, const Pose& b) { return cost(a) < cost(b); });
        return out;
    }

    std::optional<std::vector<Pose>> search(const Pose& from, const std::vector<Pose>& goals) const;

private:
    bool append_piece(const Pose& a, const Pose& b, int halvings, std::vector<Pose>& out) const {
        if (kinematics::linear_motion_clearance(task_.obstacles, robot_, a, b).worst() >= 0.0) {
            out.push_back(b);
            return true;
        }
        if (halvings <= 0) return false;
        const Pose mid = between(a, b, 0.5);
        if (!clear(mid, 0.0)) return false;
        return append_piece(a, mid, halvings - 1, out) && append_piece(mid, b, halvings - 1, out);
    }

    const task::Task& task_;
    const kinematics::Robot& robot_;
    const TravelOptions& opt_;
};

Pose pose_of(const ob::State* s, std::size_t n) {
    const auto* v = s->as<ob::RealVectorStateSpace::StateType>();
    return Pose(v->values, v->values + n);
}

void set_pose(ob::State* s, const Pose& q) {
    auto* v = s->as<ob::RealVectorStateSpace::StateType>();
    std::copy(q.begin(), q.end(), v->values);
}

// RRT-Connect in joint space (angles unwrapped, within half a turn beyond
// the start and every goal), checked at a quarter of the joint step with
// `spare` clearance, then shortened; the caller certifies the result.
std::optional<std::vector<Pose>> Planner::search(const Pose& from,
                                                 const std::vector<Pose>& goals) const {
    // Repeatable plans: OMPL seeds every planner from one process-wide seed.
    static std::once_flag seeded;
    std::call_once(seeded, [] {
        ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
        ompl::RNG::setSeed(20240611);
    });
    const std::size_t n = from.size();
    auto space = std::make_shared<ob::RealVectorStateSpace>(static_cast<unsigned>(n));
    ob::RealVectorBounds bounds(static_cast<unsigned>(n));
    for (std::size_t k = 0; k < n; ++k) {
        double lo = from[k], hi = from[k];
        for (const Pose& g : goals) lo = std::min(lo, g[k]), hi = std::max(hi, g[k]);
        bounds.setLow(static_cast<unsigned>(k), lo - geometry::kPi / 2);
        bounds.setHigh(static_cast<unsigned>(k), hi + geometry::kPi / 2);
    }
    space->setBounds(bounds);
    auto si = std::make_shared<ob::SpaceInformation>(space);
    si->setStateValidityChecker(
        [this, n](const ob::State* s) { return clear(pose_of(s, n), opt_.spare); });
    si->setStateValidityCheckingResolution(0.25 * opt_.max_joint_step / space->getMaximumExtent());
    si->setup();
    auto problem = std::make_shared<ob::ProblemDefinition>(si);
    ob::ScopedState<> start(space);
    set_pose(start.get(), from);
    problem->addStartState(start);
    auto goal = std::make_shared<ob::GoalStates>(si);
    for (const Pose& g : goals) {
        if (!clear(g, 0.0)) continue;
        ob::ScopedState<> s(space);
        set_pose(s.get(), g);
        goal->addState(s);
    }
    if (!goal->hasStates()) return std::nullopt;
    problem->setGoal(goal);
    auto planner = std::make_shared<og::RRTConnect>(si);
    planner->setProblemDefinition(problem);
    planner->setup();
    const run::Deadline until = opt_.deadline.within(opt_.plan_seconds);
    const ob::PlannerTerminationCondition stop([until] { return until.expired(); });
    if (planner->solve(stop) != ob::PlannerStatus::EXACT_SOLUTION) return std::nullopt;
    auto& path = *problem->getSolutionPath()->as<og::PathGeometric>();
    og::PathSimplifier simplifier(si);
    simplifier.reduceVertices(path);
    simplifier.shortcutPath(path);
    std::vector<Pose> out;
    for (const ob::State* s : path.getStates()) out.push_back(pose_of(s, n));
    return out;
}

}  // namespace

bool TravelOptions::IsValid(std::string* error) const {
    return text::OptionCheck("TravelOptions", error)
        .greater("max_joint_step", max_joint_step, 0.0)
        .at_least("spare", spare, 0.0)
        .at_least("plan_seconds", plan_seconds, 0.0)
        .within("max_halvings", max_halvings, 0, 30)
        .ok();
}

std::optional<TravelPlan> plan_travel(const task::Task& task, const kinematics::Robot& robot,
                                      const std::vector<double>& from,
                                      const std::vector<double>& to, const TravelOptions& options) {
    text::require_valid(options);
    const Planner planner(task, robot, options);
    const std::vector<Pose> goals = planner.goals(from, to);
    for (const Pose& g : goals) {
        if (options.deadline.expired()) return std::nullopt;
        TravelPlan plan{{}, "straight"};
        if (planner.append_line(from, g, plan.poses)) return plan;
    }
    const auto waypoints = planner.search(from, goals);
    if (!waypoints) return std::nullopt;
    TravelPlan plan{{}, "planned"};
    for (std::size_t i = 1; i < waypoints->size(); ++i)
        if (!planner.append_line((*waypoints)[i - 1], (*waypoints)[i], plan.poses))
            return std::nullopt;
    return plan;
}

}  // namespace modsynth::control
