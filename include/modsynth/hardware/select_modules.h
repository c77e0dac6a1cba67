#pragma once
// Choosing actuator modules for a solved motion: the lightest allowed module
// at each joint whose peak torque covers the largest |torque|, whose
// continuous torque covers the RMS torque, and whose speed covers the
// largest |qd|.
#include <functional>
#include <string>
#include <vector>

#include <modsynth/control/motion.h>
#include <modsynth/hardware/arm_model.h>
#include <modsynth/hardware/catalog.h>
#include <modsynth/hardware/selection.h>
#include <modsynth/kinematics/robot.h>
#include <modsynth/task/task.h>

namespace modsynth::hardware {

/// Torque and speed figures of every joint over timed samples that carry qd
/// and qdd (throws std::invalid_argument on a sample without them). RMS is
/// over time (trapezoid rule), or over samples when all share one time.
std::vector<JointLoad> joint_loads(const ArmModel& model,
                                   const std::vector<control::Sample>& samples);

/// The same for any arm whose torques at a sample `torques` gives (one per
/// joint, N m), for `dof` joints.
std::vector<JointLoad> joint_loads(
    int dof, const std::vector<control::Sample>& samples,
    const std::function<std::vector<double>(const control::Sample&)>& torques);

/// The allowed actuators of a task, lightest first: those robot.modules
/// names, each a model or a whole family ("dynamixel-x"), or without it
/// those of the catalog's default families (every actuator when no file is
/// marked "default"). Throws task::InputError naming robot.modules[i] for a
/// name that is neither, listing the families and models.
std::vector<const Actuator*> allowed_actuators(const task::RobotSpec& spec, const Catalog& catalog);
/// The same from the names of robot.modules (empty: the default families).
std::vector<const Actuator*> allowed_actuators(const std::vector<std::string>& names,
                                               const Catalog& catalog);

/// What every joint of an arm with `modules` (one per joint, joint 1 first)
/// must deliver over the motion.
using LoadsWithModules =
    std::function<std::vector<JointLoad>(const std::vector<const Actuator*>& modules)>;

/// The greedy choice for any arm of `dof` joints (select_modules below is
/// it for the planar arm): from the distal joint inwards, each joint the
/// lightest of `allowed` (lightest first) that carries it, the modules
/// farther out already chosen and those not yet chosen the lightest.
ModuleSelection choose_modules(int dof, const std::vector<const Actuator*>& allowed,
                               const LoadsWithModules& loads);

/// Chooses from the distal joint inwards: a joint's torques depend only on
/// the modules farther out, which are then already chosen, and each joint
/// takes the lightest that carries it (lighter modules outward mostly lower
/// the loads inward; the choice is greedy, not a search over all
/// combinations). Unchecked (selection.checked false) when a sample lacks
/// qd or qdd. With `printed`, the links are those printed parts (arm_model).
ModuleSelection select_modules(const task::Task& task, const kinematics::Robot& robot,
                               const std::vector<control::Sample>& samples, const Catalog& catalog,
                               const std::vector<PrintedLink>& printed = {});

}  // namespace modsynth::hardware
