#pragma once
// Solved solutions made by hand for the output tests: a 2-joint arm tracing
// a line past an obstacle, and a 3-joint arm tracing two lines with a
// transition between them (link 1 still during each trace, as in the paper).
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <modsynth/control/motion.h>
#include <modsynth/kinematics/kinematics.h>
#include <modsynth/synth/solution.h>
#include <modsynth/task/task.h>

namespace modsynth::testing {

inline task::Task two_joint_task() {
    task::Task t;
    t.name = "line";
    t.trajectory.push_back(geometry::make_line({0.40, 0.05}, {0.40, 0.30}));
    t.trajectory.push_back(geometry::make_arc({0.40, 0.30}, {0.30, 0.40}, {0.30, 0.30}, true));
    t.obstacles.push_back({{0.15, 0.45}, 0.04});
    t.obstacles.push_back({{0.55, 0.10}, 0.03});
    t.base_regions.push_back({{-0.05, -0.05}, {0.05, 0.05}});
    t.robot.dof = {2};
    return t;
}

inline synth::Solution two_joint_solution(const task::Task& task) {
    synth::Solution s;
    s.task_name = task.name;
    s.status = synth::Status::Solved;
    s.robot.base = {0.0, 0.0};
    s.robot.link_lengths = {0.35, 0.30};
    s.robot.link_diameter = task.robot.link_diameter;
    s.robot.elbow = -1;
    control::MotionOptions options;
    s.samples = *control::plan_motion(task, s.robot, options);
    control::assign_times(s.samples, options);
    s.certificate.ok = true;
    s.certificate.min_clearance = 0.0123;
    s.certificate.min_self_clearance = 0.2;
    s.certificate.max_deviation = 2.5e-5;
    s.certificate.max_joint_step = 0.0099;
    return s;
}

inline task::Task three_joint_task() {
    task::Task t;
    t.name = "corner";
    t.trajectory.push_back(geometry::make_line({0.45, 0.10}, {0.45, 0.25}));
    t.trajectory.push_back(geometry::make_line({0.45, 0.25}, {0.30, 0.25}));
    t.obstacles.push_back({{0.10, 0.40}, 0.05});
    t.robot.dof = {3};
    return t;
}

/// The distal pair's joint angles that put the EE at p with link 1 at q1.
inline std::vector<double> three_joint_q(const kinematics::Robot& r, double q1,
                                         const geometry::Vec2& p) {
    const geometry::Vec2 s2 = r.base + r.link_lengths[0] * geometry::unit(q1);
    const auto ik =
        kinematics::inverse_two_link(s2, r.link_lengths[1], r.link_lengths[2], p, r.elbow);
    return {q1, ik->phi1 - q1, ik->q2};
}

inline synth::Solution three_joint_solution(const task::Task& task) {
    synth::Solution s;
    s.task_name = task.name;
    s.status = synth::Status::Solved;
    s.robot.base = {0.0, 0.0};
    s.robot.link_lengths = {0.25, 0.22, 0.20};
    s.robot.link_diameter = task.robot.link_diameter;
    s.robot.elbow = 1;
    const double q1[2] = {0.30, 0.55};
    double t = 0.0;
    for (int j = 0; j < 2; ++j) {
        const auto& prim = task.trajectory[j];
        const int steps = 40;
        for (int i = 0; i <= steps; ++i) {
            const double u = geometry::length(prim) * i / steps;
            s.samples.push_back({t, control::Phase::Trace, j, u,
                                 three_joint_q(s.robot, q1[j], geometry::point_at(prim, u))});
            t += 0.05;
        }
        if (j == 1) break;
        for (int i = 1; i < 25; ++i) {  // link 1 turns, the EE holds still
            const double a = q1[0] + (q1[1] - q1[0]) * i / 25.0;
            s.samples.push_back(
                {t, control::Phase::Transition, j, 0.0, three_joint_q(s.robot, a, prim.end)});
            t += 0.05;
        }
    }
    s.certificate.ok = true;
    s.certificate.min_clearance = 0.05;
    s.certificate.min_self_clearance = 0.04;
    s.certificate.max_deviation = 1e-6;
    s.certificate.max_joint_step = 0.01;
    return s;
}

inline synth::Solution infeasible_solution(const task::Task& task) {
    synth::Solution s;
    s.task_name = task.name;
    s.status = synth::Status::Infeasible;
    s.explanation.message = "No robot <can> do this & that";
    s.explanation.core = {task::TaskPart::trajectory(1), task::TaskPart::obstacle(0),
                          task::TaskPart::base_regions(),
                          task::TaskPart::robot(task::RobotKey::MaxLinkLength)};
    return s;
}

/// A fresh directory for files a test writes.
inline std::filesystem::path scratch_dir(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("modsynth_output_test_" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace modsynth::testing
