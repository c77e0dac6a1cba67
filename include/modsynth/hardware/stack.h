#pragma once
// How a synthesised arm is built from actuator modules and tubes (paper
// III-G and IV): every link is a tube stacked one level higher in z than the
// previous one, so links only ever meet the end-effector rod, which runs from
// the end of the last tube down to the task plane. The build sheet and the
// URDF share these numbers so that what is cut is what is simulated.
#include <vector>

#include <modsynth/kinematics/robot.h>
#include <modsynth/task/task.h>

namespace modsynth::hardware {

/// One tube to cut. The allowances are what the module bodies and adapters
/// take from the axis-to-axis link length at each end:
/// cut_length = link_length - proximal_allowance - distal_allowance.
struct TubeCut {
    double link_length = 0.0;
    double proximal_allowance = 0.0;  ///< at the output of the module that drives it
    double distal_allowance = 0.0;    ///< at the next module's body, or the EE rod
    double cut_length = 0.0;          ///< <= 0: the link is too short for the hardware
    bool last = false;                ///< ends at the end-effector rod
};

/// Axis to the edge of the module's output end, plus the adapter.
double proximal_allowance(const task::RobotSpec& spec);
/// Axis back to the far end of the next module's body, plus the adapter.
double distal_allowance(const task::RobotSpec& spec);
/// The last tube runs past the EE axis by half its diameter, so that the
/// hole for the rod lies wholly inside it: a negative allowance.
double ee_allowance(double link_diameter);

std::vector<TubeCut> tube_cuts(const task::RobotSpec& spec, const kinematics::Robot& robot);

/// Heights above the task plane (m). Module k (0-based) stands on tube k - 1
/// (module 0 on the table), its output face up; tube k lies on that face.
double output_face_height(const task::RobotSpec& spec, double link_diameter, int k);
double tube_axis_height(const task::RobotSpec& spec, double link_diameter, int k);
/// From the top of the last tube down to the task plane.
double ee_rod_length(const task::RobotSpec& spec, double link_diameter, int dof);

}  // namespace modsynth::hardware
