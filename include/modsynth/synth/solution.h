#pragma once
// What synthesis answers: a certified robot and its control, or a reason.
#include <string>
#include <vector>

#include <modsynth/control/motion.h>
#include <modsynth/kinematics/robot.h>
#include <modsynth/synth/status.h>
#include <modsynth/verify/verifier.h>

namespace modsynth::synth {

struct Explanation {
    std::string message;
    std::vector<std::string> core;  ///< task parts, named as in formats.md
};

struct Solution {
    std::string task_name;
    Status status = Status::Unknown;
    kinematics::Robot robot;               ///< solved only
    std::vector<control::Sample> samples;  ///< solved only
    verify::Certificate certificate;       ///< solved only
    Explanation explanation;               ///< infeasible and unknown
};

}  // namespace modsynth::synth
