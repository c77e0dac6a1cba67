#pragma once
// The arm as rigid bodies for its dynamics: each link with the tube, the
// adapters, the next module's body (or the end-effector rod and the payload)
// it carries, lumped into one mass, centre of mass and moment of inertia
// about the joint axis direction. Every part lies on the link's centre line
// (in the plane; the heights of the stack do not change torques about
// vertical axes), so one coordinate along the link places it.
#include <vector>

#include <modsynth/geometry/vec.h>
#include <modsynth/hardware/catalog.h>
#include <modsynth/kinematics/robot.h>
#include <modsynth/task/task.h>

namespace modsynth::hardware {

struct LinkBody {
    double mass = 0.0;     ///< kg
    double com = 0.0;      ///< m along the link from its joint
    double inertia = 0.0;  ///< kg m^2 about the centre of mass, axis along the joints
};

struct ArmModel {
    std::vector<double> link_lengths;  ///< r_1 .. r_n, m
    std::vector<LinkBody> links;       ///< as many as link_lengths
    /// Acceleration of gravity in the plane (m/s^2); zero when it runs along
    /// the joint axes.
    geometry::Vec2 gravity = geometry::Vec2::Zero();
};

/// A link printed in one piece (parts/): what its mesh weighs, where its
/// centre of mass is along the link and its moment of inertia about that
/// centre (axis along the joints).
using PrintedLink = LinkBody;

/// Adds a part (mass at `com` along the link with its own inertia about its
/// centre) to a body: the parallel-axis theorem.
void add_part(LinkBody& body, double mass, double com, double inertia = 0.0);

/// The model of a robot built from `modules` (one per joint, module k at
/// joint k; module 1 stands on the table and loads nothing): link k carries
/// its tube (a uniform rod over its cut length), an adapter at each tube end
/// that meets a module, and module k + 1's body (a box of the task's module
/// size, behind the next axis as on the build sheet); the last link instead
/// carries the end-effector rod and the payload at the tool. Tube and rod
/// are the catalog's closest in diameter. With `printed` (one per link,
/// `modsynth solve --parts`), link k carries printed[k] in place of its tube
/// and its adapters: the printed link bolts straight to the modules.
ArmModel arm_model(const task::RobotSpec& spec, const kinematics::Robot& robot,
                   const Catalog& catalog, const std::vector<const Actuator*>& modules,
                   const std::vector<PrintedLink>& printed = {});

}  // namespace modsynth::hardware
