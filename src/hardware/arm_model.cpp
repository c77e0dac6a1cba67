#include <modsynth/hardware/arm_model.h>

#include <stdexcept>

#include <modsynth/hardware/stack.h>

namespace modsynth::hardware {

void add_part(LinkBody& body, double mass, double com, double inertia) {
    if (mass <= 0.0) return;
    const double total = body.mass + mass;
    const double c = (body.mass * body.com + mass * com) / total;
    body.inertia +=
        body.mass * (body.com - c) * (body.com - c) + inertia + mass * (com - c) * (com - c);
    body.com = c;
    body.mass = total;
}

ArmModel arm_model(const task::RobotSpec& spec, const kinematics::Robot& robot,
                   const Catalog& catalog, const std::vector<const Actuator*>& modules,
                   const std::vector<PrintedLink>& printed) {
    const int n = robot.dof();
    if (static_cast<int>(modules.size()) != n)
        throw std::invalid_argument("arm_model: one module per joint");
    if (!printed.empty() && static_cast<int>(printed.size()) != n)
        throw std::invalid_argument("arm_model: one printed link per link");
    ArmModel model;
    model.link_lengths = robot.link_lengths;
    if (spec.gravity) model.gravity = *spec.gravity;
    const Tube& tube = catalog.tube_closest_to(robot.link_diameter);
    const Tube& rod = catalog.tube_closest_to(spec.ee_rod_diameter);
    const double adapter = catalog.adapter().mass;
    const std::vector<TubeCut> cuts = tube_cuts(spec, robot);
    for (int k = 0; k < n; ++k) {
        LinkBody body;
        const TubeCut& cut = cuts[k];
        const double r = cut.link_length;
        if (!printed.empty()) {
            add_part(body, printed[k].mass, printed[k].com, printed[k].inertia);
        } else if (cut.cut_length > 0.0) {
            const double start = cut.proximal_allowance;
            const double end = r - cut.distal_allowance;
            const double m = tube.mass_per_metre * cut.cut_length;
            add_part(body, m, (start + end) / 2.0, m * cut.cut_length * cut.cut_length / 12.0);
        }
        if (printed.empty())
            add_part(body, adapter, cut.proximal_allowance - spec.adapter_length / 2.0);
        if (cut.last) {
            // The rod hangs from the tool straight down: in the plane it is
            // a point at the tool, as is the payload.
            add_part(body, rod.mass_per_metre * ee_rod_length(spec, robot.link_diameter, n), r);
            add_part(body, spec.payload, r);
        } else {
            if (printed.empty())
                add_part(body, adapter, r - cut.distal_allowance + spec.adapter_length / 2.0);
            // The next module's housing rides on this link; its output turns
            // with the next one, but its rotor and gears are light next to
            // the housing, so all of its mass is counted here.
            const double L = spec.module_length, W = spec.module_width;
            const double m = modules[k + 1]->mass;
            add_part(body, m, r - (L / 2.0 - W / 2.0), m * (L * L + W * W) / 12.0);
        }
        model.links.push_back(body);
    }
    return model;
}

}  // namespace modsynth::hardware
