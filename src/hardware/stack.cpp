#include <modsynth/hardware/stack.h>

namespace modsynth::hardware {

double proximal_allowance(const task::RobotSpec& spec) {
    return spec.module_width / 2.0 + spec.adapter_length;
}

double distal_allowance(const task::RobotSpec& spec) {
    return spec.module_length - spec.module_width / 2.0 + spec.adapter_length;
}

double ee_allowance(double link_diameter) { return -link_diameter / 2.0; }

std::vector<TubeCut> tube_cuts(const task::RobotSpec& spec, const kinematics::Robot& robot) {
    std::vector<TubeCut> cuts;
    const int n = robot.dof();
    for (int k = 0; k < n; ++k) {
        TubeCut c;
        c.link_length = robot.link_lengths[k];
        c.last = k == n - 1;
        c.proximal_allowance = proximal_allowance(spec);
        c.distal_allowance = c.last ? ee_allowance(robot.link_diameter) : distal_allowance(spec);
        c.cut_length = c.link_length - c.proximal_allowance - c.distal_allowance;
        cuts.push_back(c);
    }
    return cuts;
}

double output_face_height(const task::RobotSpec& spec, double link_diameter, int k) {
    return (k + 1) * spec.module_height + k * link_diameter;
}

double tube_axis_height(const task::RobotSpec& spec, double link_diameter, int k) {
    return output_face_height(spec, link_diameter, k) + link_diameter / 2.0;
}

double ee_rod_length(const task::RobotSpec& spec, double link_diameter, int dof) {
    return output_face_height(spec, link_diameter, dof - 1) + link_diameter;
}

}  // namespace modsynth::hardware
