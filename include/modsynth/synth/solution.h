#pragma once
// What synthesis answers: a certified robot and its control, or a reason.
#include <optional>
#include <string>
#include <vector>

#include <modsynth/control/motion.h>
#include <modsynth/hardware/selection.h>
#include <modsynth/kinematics/dh_chain.h>
#include <modsynth/kinematics/robot.h>
#include <modsynth/prove/enclosure_witness.h>
#include <modsynth/prove/wall_witness.h>
#include <modsynth/synth/status.h>
#include <modsynth/task/part.h>
#include <modsynth/verify/verifier.h>

namespace modsynth::synth {

struct Explanation {
    std::string message;
    std::vector<task::TaskPart> core;  ///< the task parts involved
    /// The data of an obstacle proof, when the task was proved infeasible
    /// that way (formats.md, "explanation.separation", ".geodesic").
    std::optional<prove::SeparationWitness> separation;
    std::optional<prove::GeodesicWitness> geodesic;
    /// A spatial task's closed shell (formats.md "Spatial tasks",
    /// "explanation.enclosure").
    std::optional<prove::EnclosureWitness> enclosure;
};

struct Solution {
    std::string task_name;
    Status status = Status::Unknown;
    kinematics::Robot robot;               ///< solved only
    std::vector<control::Sample> samples;  ///< solved only
    verify::Certificate certificate;       ///< solved only
    Explanation explanation;               ///< infeasible and unknown
    /// Solved only, when modules were chosen for the motion (it must carry
    /// qd and qdd): the actuator at each joint, or the joint none carries.
    std::optional<hardware::ModuleSelection> modules;
    /// Solved spatial tasks only: the robot as a DH chain (formats.md
    /// "Spatial tasks"), in place of `robot`, which is then unused.
    std::optional<kinematics::DhChain> dh_robot;
};

}  // namespace modsynth::synth
