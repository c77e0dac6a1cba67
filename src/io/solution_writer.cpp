#include <modsynth/io/solution_io.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include <modsynth/io/atomic_file.h>
#include <modsynth/io/json_numbers.h>
#include <modsynth/task/limits.h>

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

nlohmann::json to_json(const prove::EnclosureWitness& w) {
    const auto point3 = [](const geometry::Vec3& p) { return nlohmann::json{p.x(), p.y(), p.z()}; };
    nlohmann::json walls = nlohmann::json::array();
    for (const auto& x : w.walls) {
        nlohmann::json cells = nlohmann::json::array();
        for (const auto& r : x.cells) cells.push_back({r.j, r.k, r.i0, r.i1});
        walls.push_back(
            {{"base_region", x.base_region},
             {"primitive", x.primitive},
             {"point", point3(x.point)},
             {"obstacles", x.obstacles},
             {"grid",
              {{"origin", point3(x.grid.origin)}, {"cell", x.grid.cell}, {"size", x.grid.size}}},
             {"inside", x.base_inside ? "base_region" : "point"},
             {"cells", cells}});
    }
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
        if (!j.family.empty()) joints.back()["family"] = j.family;
        if (j.cost) joints.back()["cost"] = *j.cost;
    }
    nlohmann::json out = {{"joints", joints},
                          {"total_mass", m.total_mass},
                          {"overloaded_joint", nullptr},
                          {"message", m.message},
                          {"cost", m.cost}};
    if (m.total_cost) out["total_cost"] = *m.total_cost;
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
    if (e.enclosure) out["enclosure"] = to_json(*e.enclosure);
}

namespace {

const char* phase_name(control::Phase phase) {
    switch (phase) {
        case control::Phase::Trace:
            return "trace";
        case control::Phase::Transition:
            return "transition";
        case control::Phase::Travel:
            return "travel";
    }
    return "trace";
}

// Numbers exactly as nlohmann's serializer writes them (shortest
// round-trip text, "1.0" for integral values, null for non-finite ones).
void append_number(std::string& out, double v) {
    if (!std::isfinite(v)) {
        out += "null";
        return;
    }
    std::array<char, 64> buf{};
    char* end = nlohmann::detail::to_chars(buf.data(), buf.data() + buf.size(), v);
    out.append(buf.data(), end);
}

bool has_strokes(const std::vector<control::Sample>& samples) {
    return std::any_of(samples.begin(), samples.end(),
                       [](const control::Sample& x) { return x.stroke != 0; });
}

void append_array(std::string& out, const char* key, const std::vector<double>& values) {
    out += "\n   \"";
    out += key;
    out += "\": [";
    if (values.empty()) {
        out += "]";
        return;
    }
    for (std::size_t i = 0; i < values.size(); ++i) {
        out += i ? ",\n    " : "\n    ";
        append_number(out, values[i]);
    }
    out += "\n   ]";
}

/// Sample i as a member of `to_json(solution).dump(1)`'s "samples" array
/// (keys in nlohmann's sorted order), its separator before it.
void append_sample(std::string& out, const control::Sample& x, std::size_t i, bool strokes) {
    out += i ? ",\n  {" : "\n  {";
    out += "\n   \"phase\": \"";
    out += phase_name(x.phase);
    out += "\",\n   \"primitive\": ";
    out += std::to_string(x.primitive);
    out += ",";
    append_array(out, "q", x.q);
    if (!x.qd.empty()) {
        out += ",";
        append_array(out, "qd", x.qd);
    }
    if (!x.qdd.empty()) {
        out += ",";
        append_array(out, "qdd", x.qdd);
    }
    if (strokes) out += ",\n   \"stroke\": " + std::to_string(x.stroke);
    out += ",\n   \"t\": ";
    append_number(out, x.t);
    out += "\n  }";
}

nlohmann::json document(const synth::Solution& s, bool with_samples) {
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
        doc["robot"] = io::to_json(*s.dh_robot);
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
    const bool strokes = has_strokes(s.samples);
    nlohmann::json samples = nlohmann::json::array();
    if (with_samples) {
        for (const auto& x : s.samples) {
            nlohmann::json sample = {
                {"t", x.t}, {"phase", phase_name(x.phase)}, {"primitive", x.primitive}, {"q", x.q}};
            if (!x.qd.empty()) sample["qd"] = x.qd;
            if (!x.qdd.empty()) sample["qdd"] = x.qdd;
            if (strokes) sample["stroke"] = x.stroke;
            samples.push_back(std::move(sample));
        }
    }
    doc["samples"] = std::move(samples);
    const auto& c = s.certificate;
    doc["certificate"] = {{"min_clearance_margin", finite_or_null(c.min_clearance)},
                          {"min_self_collision_margin", finite_or_null(c.min_self_clearance)},
                          {"max_ee_deviation", c.max_deviation},
                          {"max_joint_step", c.max_joint_step}};
    // formats.md "Tool orientation": only where some primitive has a tool axis.
    if (std::isfinite(c.min_tool_angle_margin))
        doc["certificate"]["min_tool_angle_margin"] = c.min_tool_angle_margin;
    if (s.modules && s.modules->checked) doc["modules"] = to_json(*s.modules);
    return doc;
}

}  // namespace

nlohmann::json to_json(const synth::Solution& s) { return document(s, true); }

void write_solution(const synth::Solution& solution, const std::string& path) {
    // A motion has up to hundreds of thousands of samples: building a JSON
    // value per sample took longer than the rest of a solve on long tasks,
    // and holding the text whole several times the file's size. The
    // samples are written straight into the file, a piece at a time, as the
    // text `to_json(solution).dump(1)` gives, byte for byte.
    const std::string text = document(solution, false).dump(1);
    const std::string empty = "\n \"samples\": []";
    const std::size_t at = text.find(empty);
    std::error_code ec;
    const auto st = std::filesystem::status(path, ec);
    const bool device = std::filesystem::exists(st) && !std::filesystem::is_regular_file(st) &&
                        !std::filesystem::is_directory(st);
    if (at == std::string::npos || solution.samples.empty() || device) {
        std::string whole = text;
        if (at != std::string::npos && !solution.samples.empty()) {
            std::string samples = "\n \"samples\": [";
            const bool strokes = has_strokes(solution.samples);
            for (std::size_t i = 0; i < solution.samples.size(); ++i)
                append_sample(samples, solution.samples[i], i, strokes);
            whole.replace(at, empty.size(), samples + "\n ]");
        }
        return write_file_atomically(path, whole + '\n');
    }
    AtomicFile file(path);
    file.write(std::string_view(text).substr(0, at));
    std::string piece = "\n \"samples\": [";
    constexpr std::size_t kPiece = 1u << 20;
    piece.reserve(kPiece + 4096);
    const bool strokes = has_strokes(solution.samples);
    // The planners keep a motion within what a file holds
    // (task::max_motion_samples); a file past the readers' cap all the same
    // (a task name of megabytes) is not left behind as if it could be read.
    const auto put = [&] {
        if (file.bytes() + piece.size() > task::kMaxSolutionBytes)
            throw WriteError(path + ": the solution would take more than the " +
                             std::to_string(task::kMaxSolutionBytes) +
                             " bytes a solution file may have; not written");
        file.write(piece);
        piece.clear();
    };
    for (std::size_t i = 0; i < solution.samples.size(); ++i) {
        append_sample(piece, solution.samples[i], i, strokes);
        if (piece.size() >= kPiece) put();
    }
    piece += "\n ]";
    piece.append(text, at + empty.size(), std::string::npos);
    piece += '\n';
    put();
    file.commit();
}

}  // namespace modsynth::io
