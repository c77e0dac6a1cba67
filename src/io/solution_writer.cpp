#include <modsynth/io/solution_io.h>

#include <nlohmann/json.hpp>

#include <modsynth/io/atomic_file.h>
#include <modsynth/io/json_numbers.h>

namespace modsynth::io {
namespace {

nlohmann::json point(const geometry::Vec2& p) { return {p.x(), p.y()}; }

nlohmann::json to_json(const synth::SeparationWitness& w) {
    nlohmann::json walls = nlohmann::json::array();
    for (const auto& x : w.walls)
        walls.push_back({{"base_region", x.base_region},
                         {"primitive", x.primitive},
                         {"point", point(x.point)},
                         {"cycle", x.cycle},
                         {"overlaps", x.overlaps}});
    return {{"walls", walls}};
}

nlohmann::json to_json(const synth::GeodesicWitness& w) {
    nlohmann::json detours = nlohmann::json::array();
    for (const auto& d : w.detours) {
        nlohmann::json route = nlohmann::json::array();
        for (const auto& s : d.route) {
            nlohmann::json step = {{"point", point(s.point)}};
            if (s.around >= 0) step["around"] = s.around;
            route.push_back(step);
        }
        detours.push_back({{"base_region", d.base_region},
                           {"primitive", d.primitive},
                           {"point", point(d.point)},
                           {"lower_bound", d.lower_bound},
                           {"route", route}});
    }
    return {{"reach", w.reach}, {"obstacles", w.obstacles}, {"detours", detours}};
}

}  // namespace

nlohmann::json to_json(const synth::Solution& s) {
    nlohmann::json doc;
    doc["format"] = "modsynth-solution/1";
    doc["task"] = s.task_name;
    doc["status"] = synth::to_string(s.status);
    if (s.status != synth::Status::Solved) {
        doc["explanation"] = {{"message", s.explanation.message}, {"core", s.explanation.core}};
        if (s.explanation.separation)
            doc["explanation"]["separation"] = to_json(*s.explanation.separation);
        if (s.explanation.geodesic)
            doc["explanation"]["geodesic"] = to_json(*s.explanation.geodesic);
        return doc;
    }
    const auto& r = s.robot;
    doc["robot"] = {{"dof", r.dof()},
                    {"base", {r.base.x(), r.base.y()}},
                    {"link_lengths", r.link_lengths},
                    {"link_diameter", r.link_diameter},
                    {"elbow", r.elbow}};
    nlohmann::json samples = nlohmann::json::array();
    for (const auto& x : s.samples) {
        nlohmann::json sample = {
            {"t", x.t},
            {"phase", x.phase == control::Phase::Trace ? "trace" : "transition"},
            {"primitive", x.primitive},
            {"q", x.q}};
        if (!x.qd.empty()) sample["qd"] = x.qd;
        if (!x.qdd.empty()) sample["qdd"] = x.qdd;
        samples.push_back(std::move(sample));
    }
    doc["samples"] = std::move(samples);
    const auto& c = s.certificate;
    doc["certificate"] = {{"min_clearance_margin", finite_or_null(c.min_clearance)},
                          {"min_self_collision_margin", finite_or_null(c.min_self_clearance)},
                          {"max_ee_deviation", c.max_deviation},
                          {"max_joint_step", c.max_joint_step}};
    return doc;
}

void write_solution(const synth::Solution& solution, const std::string& path) {
    write_file_atomically(path, to_json(solution).dump(1) + '\n');
}

}  // namespace modsynth::io
