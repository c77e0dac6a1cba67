#pragma once
// Choosing actuator modules for a solved spatial motion, as in the plane
// (hardware/select_modules.h): from the last joint inwards, the lightest
// allowed module whose peak torque, continuous (RMS) torque and speed cover
// the joint, with torques from the DH chain's inverse dynamics under
// gravity (hardware/dh_dynamics.h).
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <modsynth/control/motion.h>
#include <modsynth/hardware/catalog.h>
#include <modsynth/hardware/dh_arm_model.h>
#include <modsynth/hardware/selection.h>
#include <modsynth/kinematics/dh_chain.h>
#include <modsynth/task/spatial_task.h>

namespace modsynth::hardware {

/// Torque and speed figures of every joint over timed samples (throws
/// std::invalid_argument on a sample without qd and qdd).
std::vector<JointLoad> joint_loads(const DhArmModel& model,
                                   const std::vector<control::Sample>& samples);

/// Unchecked (selection.checked false, `message` says why) when a sample
/// lacks qd or qdd. Throws task::InputError naming robot.modules[i] for a
/// name the catalog does not have. With `printed`, those links' a parts are
/// the printed parts (dh_arm_model).
ModuleSelection select_modules(const task::SpatialTask& task, const kinematics::DhChain& chain,
                               const std::vector<control::Sample>& samples, const Catalog& catalog,
                               const std::vector<PrintedDhLink>& printed = {});

/// The modules a spatial arm is drawn and described with when none were
/// chosen for a load: the strongest allowed (by peak torque) at every joint.
std::vector<const Actuator*> strongest_modules(const task::SpatialTask& task, int dof,
                                               const Catalog& catalog);

/// The shipped catalog (load_default_catalog) with the task's module names
/// checked: throws task::InputError naming robot.modules[i] for a name it
/// lacks, and CatalogError when a task that names modules finds no catalog.
/// Without one, a task that names no modules gets none and `note` says why.
std::optional<Catalog> spatial_catalog(const task::SpatialTask& task, std::string* note);

/// The joint speed every allowed module reaches, a cap for timing a task
/// that names modules but no robot.joint_limits (infinity otherwise).
double module_speed_cap(const task::SpatialTask& task, const std::optional<Catalog>& catalog);

}  // namespace modsynth::hardware
