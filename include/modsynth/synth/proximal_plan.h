#pragma once
// Three joints, the design fixed (base, link lengths, elbow sign): where the
// proximal link stands while each primitive is traced, chosen by dynamic
// programming along the path. A node is (primitive, proximal angle on a
// grid) where the distal pair traces the primitive clear of the obstacles
// and of link 1; an edge is a transition whose sweep of the first joint,
// the short way round, keeps every pose at the transition point clear. The
// cheapest sequence moves the proximal link least and keeps clear of the
// obstacles by more where it can; its cost is linear in the primitives.
#include <string>
#include <vector>

#include <modsynth/kinematics/robot.h>
#include <modsynth/run/deadline.h>
#include <modsynth/task/task.h>

namespace modsynth::synth {

struct ProximalPlanOptions {
    /// First-joint angles on the grid (720: every half degree). A sweep
    /// passes through every grid angle between its ends, so the grid is
    /// also the step the transitions are checked at.
    int angles = 720;
    /// m between the points of a primitive a node is checked at (its ends
    /// always are). The verifier decides between them.
    double spacing = 0.004;
    /// m of clearance every checked pose keeps (reach, obstacles, the tool
    /// against links 1 and 2): the slack for what lies between the checked
    /// points and grid angles, where the verifier's bounds must still hold.
    double margin = 0.003;
    /// m of clearance past `margin` a node is charged for lacking, at
    /// `clearance_weight` per metre, against the elbow's travel in metres:
    /// the plan stays farther from the obstacles where that costs little
    /// motion.
    double wanted_clearance = 0.01;
    double clearance_weight = 10.0;
    /// Initial guesses (designs) a skeleton's plans are tried for before any
    /// of them is refined: a plan costs tens of milliseconds where a
    /// refinement of a long path costs seconds, and the guesses are scored
    /// on a coarser model of the motion than the plan.
    int guesses = 8;

    /// False (with `error` naming the field) when some value is out of range.
    bool IsValid(std::string* error) const;
};

struct ProximalPlan {
    bool found = false;
    /// One per primitive, on the grid, in [0, 2 pi) (when found).
    std::vector<double> angles;
    /// Transitions in which the proximal link moves (when found).
    int moves = 0;
    /// Least margin of the plan's nodes at their checked points (m).
    double margin = 0.0;
    /// When not found: the first primitive no sequence reaches (index in
    /// task.trajectory), and what stopped it there.
    int blocked_primitive = -1;
    std::string message;
};

/// The plan for `design` (dof 3; its proximal_angles are ignored). Stops at
/// the deadline with found = false. Throws std::invalid_argument when the
/// options are not valid or the design has not three joints.
ProximalPlan plan_proximal_angles(const task::Task& task, const kinematics::Robot& design,
                                  const ProximalPlanOptions& options = {},
                                  run::Deadline deadline = {});

}  // namespace modsynth::synth
