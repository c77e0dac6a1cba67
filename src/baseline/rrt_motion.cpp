#include <modsynth/baseline/rrt_motion.h>

#include <cmath>
#include <memory>
#include <random>

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateSampler.h>
#include <ompl/base/spaces/SO2StateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/util/Console.h>

#include <modsynth/geometry/vec.h>
#include <modsynth/kinematics/kinematics.h>
#include <modsynth/kinematics/pose_clearance.h>
#include <modsynth/run/deadline.h>
#include <modsynth/text/option_check.h>

namespace modsynth::baseline {
namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;
using geometry::kPi;

std::vector<double> angles_of(const ob::State* state, int n) {
    const auto* c = state->as<ob::CompoundState>();
    std::vector<double> q(n);
    for (int i = 0; i < n; ++i) q[i] = c->as<ob::SO2StateSpace::StateType>(i)->value;
    return q;
}

void set_angles(ob::State* state, const std::vector<double>& q) {
    auto* c = state->as<ob::CompoundState>();
    for (std::size_t i = 0; i < q.size(); ++i)
        c->as<ob::SO2StateSpace::StateType>(i)->value = std::remainder(q[i], geometry::kTau);
}

// Uniform joint angles, or with probability `bias` the goal itself: the
// goal bias lives here rather than in RRT so that every random draw comes
// from one generator seeded by the caller, and plans are repeatable.
class BiasedSampler : public ob::StateSampler {
public:
    BiasedSampler(const ob::StateSpace* space, int n, std::vector<double> goal, double bias,
                  unsigned seed)
        : ob::StateSampler(space), n_(n), goal_(std::move(goal)), bias_(bias), random_(seed) {}

    void sampleUniform(ob::State* state) override {
        if (unit_(random_) < bias_) {
            set_angles(state, goal_);
            return;
        }
        std::vector<double> q(n_);
        for (double& a : q) a = -kPi + geometry::kTau * unit_(random_);
        set_angles(state, q);
    }

    void sampleUniformNear(ob::State* state, const ob::State* near, double distance) override {
        std::vector<double> q = angles_of(near, n_);
        for (double& a : q) a += distance * (2.0 * unit_(random_) - 1.0);
        set_angles(state, q);
    }

    void sampleGaussian(ob::State* state, const ob::State* mean, double deviation) override {
        std::normal_distribution<double> normal(0.0, deviation);
        std::vector<double> q = angles_of(mean, n_);
        for (double& a : q) a += normal(random_);
        set_angles(state, q);
    }

private:
    int n_;
    std::vector<double> goal_;
    double bias_;
    std::mt19937_64 random_;
    std::uniform_real_distribution<double> unit_{0.0, 1.0};
};

// Greedy shortcut: from each kept waypoint, jump to the farthest later one
// that a straight joint-space motion reaches safely.
std::vector<ob::State*> shortcut(const ob::SpaceInformationPtr& si,
                                 const std::vector<ob::State*>& states) {
    std::vector<ob::State*> kept{states.front()};
    std::size_t i = 0;
    while (i + 1 < states.size()) {
        std::size_t j = states.size() - 1;
        while (j > i + 1 && !si->checkMotion(states[i], states[j])) --j;
        kept.push_back(states[j]);
        i = j;
    }
    return kept;
}

}  // namespace

bool PlannerOptions::IsValid(std::string* error) const {
    return text::OptionCheck("PlannerOptions", error)
        .within("goal_bias", goal_bias, 0.0, 1.0)
        .at_least("range", range, 0.0)
        .greater("resolution", resolution, 0.0)
        .at_least("max_iterations", max_iterations, 1)
        .at_least("time_limit", time_limit, 0.0)
        .ok();
}

PlannedMotion plan_rrt(const task::Task& task, const kinematics::Robot& robot,
                       const std::vector<std::vector<double>>& poses,
                       const PlannerOptions& options) {
    text::require_valid(options);
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    const run::Deadline deadline = run::Deadline::in(options.time_limit);
    const int n = robot.dof();
    PlannedMotion motion;
    if (poses.empty()) {
        motion.message = "no poses to connect";
        return motion;
    }
    auto space = std::make_shared<ob::CompoundStateSpace>();
    for (int i = 0; i < n; ++i) space->addSubspace(std::make_shared<ob::SO2StateSpace>(), 1.0);
    // Pair k's goal, read by the sampler allocator when pair k's planner is set up.
    std::vector<double> goal;
    unsigned pair_seed = 0;
    space->setStateSamplerAllocator([&](const ob::StateSpace* s) -> ob::StateSamplerPtr {
        return std::make_shared<BiasedSampler>(s, n, goal, options.goal_bias, pair_seed);
    });
    auto si = std::make_shared<ob::SpaceInformation>(space);
    si->setStateValidityChecker([&task, &robot, n](const ob::State* s) {
        return kinematics::pose_clearance(task.obstacles, robot, angles_of(s, n)).worst() >= 0.0;
    });
    si->setStateValidityCheckingResolution(options.resolution / space->getMaximumExtent());
    si->setup();

    motion.waypoints.push_back(poses.front());
    for (std::size_t k = 0; k + 1 < poses.size(); ++k) {
        goal = poses[k + 1];
        pair_seed = options.seed * 7919u + static_cast<unsigned>(k);
        ob::ScopedState<> from(space), to(space);
        set_angles(from.get(), poses[k]);
        set_angles(to.get(), poses[k + 1]);
        auto problem = std::make_shared<ob::ProblemDefinition>(si);
        problem->setStartAndGoalStates(from, to, 1e-9);
        auto planner = std::make_shared<og::RRT>(si);
        planner->setGoalBias(0.0);
        if (options.range > 0.0) planner->setRange(options.range);
        planner->setProblemDefinition(problem);
        planner->setup();
        int iterations = 0;
        const ob::PlannerTerminationCondition stop(
            [&] { return ++iterations > options.max_iterations || deadline.expired(); });
        const ob::PlannerStatus status = planner->solve(stop);
        motion.iterations += iterations;
        if (status != ob::PlannerStatus::EXACT_SOLUTION) {
            motion.failed_pair = static_cast<int>(k);
            motion.message = "RRT found no collision-free motion from point " + std::to_string(k) +
                             " to point " + std::to_string(k + 1) + " within " +
                             std::to_string(options.max_iterations) + " iterations" +
                             (deadline.expired() ? " (time limit reached)" : "");
            return motion;
        }
        auto& path = *problem->getSolutionPath()->as<og::PathGeometric>();
        std::vector<ob::State*> states = path.getStates();
        if (options.shortcut) states = shortcut(si, states);
        for (std::size_t i = 1; i < states.size(); ++i) {
            std::vector<double> q = angles_of(states[i], n);
            const std::vector<double>& last = motion.waypoints.back();
            for (int j = 0; j < n; ++j) q[j] = kinematics::unwrap_near(q[j], last[j]);
            motion.waypoints.push_back(q);
        }
    }
    motion.complete = true;
    return motion;
}

}  // namespace modsynth::baseline
