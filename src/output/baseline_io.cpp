#include <modsynth/output/baseline_io.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include <modsynth/io/json_numbers.h>

namespace modsynth::output {
namespace {

nlohmann::json robot_json(const kinematics::Robot& r) {
    return {{"dof", r.dof()},
            {"base", {r.base.x(), r.base.y()}},
            {"link_lengths", r.link_lengths},
            {"total_length", r.total_length()},
            {"link_diameter", r.link_diameter},
            {"elbow", r.elbow}};
}

nlohmann::json ratio(double a, double b) {
    return b > 0.0 && std::isfinite(a) && std::isfinite(b) ? nlohmann::json(a / b)
                                                           : nlohmann::json(nullptr);
}

}  // namespace

nlohmann::json to_json(const baseline::Fidelity& f) {
    return {{"max_ee_deviation", f.max_deviation},
            {"mean_ee_deviation", f.mean_deviation},
            {"worst_ee_point", {f.worst_point.x(), f.worst_point.y()}},
            {"coverage_gap", f.coverage_gap},
            {"path_length", f.path_length},
            {"path_outside_reachable_space", f.outside_length},
            {"whole_path_reachable", f.whole_path_reachable()},
            {"min_clearance_margin", io::finite_or_null(f.min_clearance)}};
}

nlohmann::json to_json(const baseline::BaselineResult& r, bool with_motion) {
    nlohmann::json doc;
    doc["format"] = "modsynth-baseline/1";
    doc["status"] = baseline::to_string(r.status);
    if (!r.message.empty()) doc["message"] = r.message;
    nlohmann::json points = nlohmann::json::array();
    for (const auto& p : r.points)
        points.push_back(
            {{"primitive", p.primitive}, {"s", p.s}, {"point", {p.point.x(), p.point.y()}}});
    doc["points"] = std::move(points);
    doc["seconds"] = {
        {"design", r.design_seconds}, {"planning", r.planning_seconds}, {"total", r.seconds}};
    doc["nlp_solves"] = r.design.nlp_solves;
    if (!r.design.found) return doc;
    doc["robot"] = robot_json(r.design.robot);
    doc["elbows"] = r.design.elbows;
    doc["rrt_iterations"] = r.motion.iterations;
    doc["figures"] = to_json(r.fidelity);
    if (with_motion) {
        doc["poses"] = r.design.poses;
        doc["waypoints"] = r.motion.waypoints;
    }
    return doc;
}

nlohmann::json to_json(const baseline::Comparison& c) {
    nlohmann::json doc;
    doc["format"] = "modsynth-comparison/1";
    doc["task"] = c.solution.task_name;
    nlohmann::json ours = {{"status", synth::to_string(c.solution.status)},
                           {"seconds", c.solve_seconds}};
    if (c.solution.status == synth::Status::Solved) {
        ours["robot"] = robot_json(c.solution.robot);
        ours["certified_max_ee_deviation"] = c.solution.certificate.max_deviation;
    }
    if (c.fidelity) ours["figures"] = to_json(*c.fidelity);
    doc["modsynth"] = std::move(ours);
    doc["discretized"] = to_json(c.baseline, false);
    nlohmann::json ratios;
    ratios["time"] = ratio(c.baseline.seconds, c.solve_seconds);
    if (c.fidelity && c.baseline.design.found) {
        ratios["max_ee_deviation"] =
            ratio(c.baseline.fidelity.max_deviation, c.fidelity->max_deviation);
        ratios["total_length"] =
            ratio(c.baseline.design.robot.total_length(), c.solution.robot.total_length());
    }
    doc["baseline_over_modsynth"] = std::move(ratios);
    return doc;
}

}  // namespace modsynth::output
