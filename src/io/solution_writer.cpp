#include <modsynth/io/solution_io.h>

#include <algorithm>

#include <nlohmann/json.hpp>

#include <modsynth/io/atomic_file.h>
#include <modsynth/io/json_numbers.h>

namespace modsynth::io {
namespace {

nlohmann::json point(const geometry::Vec2& p) { return {p.x(), p.y()}; }

}  // namespace

nlohmann::json to_json(const prove::SeparationWitness& w) {
    nlohmann::json walls = nlohmann::json::array();
    for (const auto& x : w.walls)
        walls.push_back({{"base_region", x.base_region},
                         {"primitive", x.primitive},
                         {"point", point(x.point)},
                         {"cycle", x.cycle},
                         {"overlaps", x.overlaps}});
    return {{"walls", walls}};
}

nlohmann::json to_json(const prove::GeodesicWitness& w) {
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

namespace {

/// The modules chosen for the motion (formats.md, "Modules").
nlohmann::json to_json(const hardware::ModuleSelection& m) {
    nlohmann::json joints = nlohmann::json::array();
    for (const auto& j : m.joints) {
        joints.push_back({{"module", j.module},
                          {"mass", j.mass},
                          {"peak_torque", j.load.peak_torque},
                          {"peak_time", j.load.peak_time},
                          {"rms_torque", j.load.rms_torque},
                          {"max_speed", j.load.max_speed},
                          {"peak_torque_margin", j.peak_margin},
                          {"continuous_torque_margin", j.continuous_margin},
                          {"speed_margin", j.speed_margin},
                          {"carries", j.carries}});
    }
    nlohmann::json out = {{"joints", joints},
                          {"total_mass", m.total_mass},
                          {"overloaded_joint", nullptr},
                          {"message", m.message}};
    if (m.overloaded_joint > 0) out["overloaded_joint"] = m.overloaded_joint;
    return out;
}

}  // namespace

nlohmann::json to_json(const kinematics::DhChain& chain) {
    nlohmann::json dh = nlohmann::json::array();
    for (const auto& row : chain.rows)
        dh.push_back({{"a", row.a}, {"alpha", row.alpha}, {"d", row.d}});
    return {{"dof", chain.dof()},
            {"base", {chain.base.x(), chain.base.y(), chain.base.z()}},
            {"dh", dh},
            {"link_diameter", chain.link_diameter}};
}

void add_witnesses(const synth::Explanation& e, nlohmann::json& out) {
    if (e.separation) out["separation"] = to_json(*e.separation);
    if (e.geodesic) out["geodesic"] = to_json(*e.geodesic);
}

nlohmann::json to_json(const synth::Solution& s) {
    nlohmann::json doc;
    doc["format"] = "modsynth-solution/1";
    doc["task"] = s.task_name;
    doc["status"] = synth::to_string(s.status);
    if (s.status != synth::Status::Solved) {
        doc["explanation"] = {{"message", s.explanation.message},
                              {"core", task::to_strings(s.explanation.core)}};
        add_witnesses(s.explanation, doc["explanation"]);
        return doc;
    }
    if (s.dh_robot) {
        doc["robot"] = to_json(*s.dh_robot);
    } else {
        const auto& r = s.robot;
        doc["robot"] = {{"dof", r.dof()},
                        {"base", {r.base.x(), r.base.y()}},
                        {"link_lengths", r.link_lengths},
                        {"link_diameter", r.link_diameter},
                        {"elbow", r.elbow}};
    }
    // `stroke` only when the motion has several (formats.md "Several
    // strokes": default 0), so one-stroke solutions read as the base format.
    const bool strokes = std::any_of(s.samples.begin(), s.samples.end(),
                                     [](const control::Sample& x) { return x.stroke != 0; });
    nlohmann::json samples = nlohmann::json::array();
    for (const auto& x : s.samples) {
        const char* phase = x.phase == control::Phase::Trace        ? "trace"
                            : x.phase == control::Phase::Transition ? "transition"
                                                                    : "travel";
        nlohmann::json sample = {
            {"t", x.t}, {"phase", phase}, {"primitive", x.primitive}, {"q", x.q}};
        if (!x.qd.empty()) sample["qd"] = x.qd;
        if (!x.qdd.empty()) sample["qdd"] = x.qdd;
        if (strokes) sample["stroke"] = x.stroke;
        samples.push_back(std::move(sample));
    }
    doc["samples"] = std::move(samples);
    const auto& c = s.certificate;
    doc["certificate"] = {{"min_clearance_margin", finite_or_null(c.min_clearance)},
                          {"min_self_collision_margin", finite_or_null(c.min_self_clearance)},
                          {"max_ee_deviation", c.max_deviation},
                          {"max_joint_step", c.max_joint_step}};
    if (s.modules && s.modules->checked) doc["modules"] = to_json(*s.modules);
    return doc;
}

void write_solution(const synth::Solution& solution, const std::string& path) {
    write_file_atomically(path, to_json(solution).dump(1) + '\n');
}

}  // namespace modsynth::io
