// docs/formats.md is the project's format contract: a verbatim superset of
// the shared ../shared/spec/formats.md plus the project's optional keys.
// These tests keep it honest: every JSON example in either document is read
// by modsynth's own parsers (with the values they state), the project copy
// still holds every line of the shared one in order, and what the document
// says about the extensions modsynth does not implement yet is still true.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <modsynth/hardware/catalog.h>
#include <modsynth/io/solution_io.h>
#include <modsynth/io/spatial_task_io.h>
#include <modsynth/io/task_io.h>

using modsynth::io::parse_solution;
using modsynth::io::parse_task;
using modsynth::task::InputError;
using nlohmann::json;

namespace {

const std::string kProjectFormats = MODSYNTH_SOURCE_DIR "/docs/formats.md";

/// The shared contract, beside the repository; MODSYNTH_SHARED_FORMATS
/// overrides the path (e.g. when the repository is checked out elsewhere).
std::string shared_formats_path() {
    if (const char* p = std::getenv("MODSYNTH_SHARED_FORMATS"); p && *p) return p;
    return MODSYNTH_SOURCE_DIR "/../shared/spec/formats.md";
}

bool read_lines(const std::string& path, std::vector<std::string>& lines) {
    std::ifstream in(path);
    if (!in) return false;
    lines.clear();
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return true;
}

struct Block {
    int line = 0;  ///< 1-based line of the opening fence
    std::string text;
};

/// Every fenced ```json block, in order.
std::vector<Block> json_blocks(const std::vector<std::string>& lines) {
    std::vector<Block> out;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (lines[i] != "```json") continue;
        Block b;
        b.line = static_cast<int>(i) + 1;
        std::size_t k = i + 1;
        for (; k < lines.size() && lines[k] != "```"; ++k) b.text += lines[k] + "\n";
        REQUIRE(k < lines.size());  // every block is closed
        out.push_back(b);
        i = k;
    }
    return out;
}

double number_or_infinity(const json& j) {
    return j.is_null() ? std::numeric_limits<double>::infinity() : j.get<double>();
}

/// The task example is read, and every value it states is the value read.
void check_task_example(const json& doc) {
    const modsynth::task::Task task = parse_task(doc);
    if (doc.contains("strokes")) {
        std::size_t primitives = 0;
        for (const json& stroke : doc["strokes"]) primitives += stroke.size();
        REQUIRE(task.trajectory.size() == primitives);
        CHECK(task.stroke_starts.size() == doc["strokes"].size());
    } else {
        REQUIRE(task.trajectory.size() == doc.at("trajectory").size());
    }
    CHECK(task.obstacles.size() == doc.value("obstacles", json::array()).size());
    CHECK(task.base_regions.size() == doc.value("base_regions", json::array()).size());
    if (doc.contains("name")) CHECK(task.name == doc["name"].get<std::string>());
    if (!doc.contains("robot")) return;
    const json& r = doc["robot"];
    const auto& spec = task.robot;
    if (r.contains("dof")) CHECK(spec.dof == r["dof"].get<std::vector<int>>());
    const std::pair<const char*, double> keys[] = {
        {"link_diameter", spec.link_diameter},     {"min_link_length", spec.min_link_length},
        {"max_link_length", spec.max_link_length}, {"module_length", spec.module_length},
        {"module_width", spec.module_width},       {"module_height", spec.module_height},
        {"adapter_length", spec.adapter_length},   {"ee_rod_diameter", spec.ee_rod_diameter}};
    for (const auto& [key, value] : keys) {
        if (r.contains(key)) {
            INFO("robot." << key);
            CHECK(value == Approx(r[key].get<double>()));
        }
    }
}

/// The solution example is read (parsing only: an example with two samples
/// need not pass verification), with the values it states.
void check_solution_example(const json& doc) {
    const modsynth::io::ParsedSolution parsed = parse_solution(doc);
    const modsynth::synth::Solution& s = parsed.solution;
    CHECK(modsynth::synth::to_string(s.status) == doc.at("status").get<std::string>());
    if (doc.contains("task")) CHECK(s.task_name == doc["task"].get<std::string>());
    if (doc["status"] != "solved") {
        CHECK(s.explanation.message == doc.at("explanation").at("message").get<std::string>());
        CHECK(modsynth::task::to_strings(s.explanation.core) ==
              doc["explanation"].value("core", std::vector<std::string>{}));
        return;
    }
    const json& r = doc.at("robot");
    CHECK(s.robot.dof() == r.at("dof").get<int>());
    CHECK(s.robot.link_lengths == r.at("link_lengths").get<std::vector<double>>());
    CHECK(s.robot.base.x() == r.at("base")[0].get<double>());
    CHECK(s.robot.base.y() == r.at("base")[1].get<double>());
    if (r.contains("elbow")) {
        CHECK(s.robot.elbow == r["elbow"].get<int>());
    } else {
        CHECK(std::abs(s.robot.elbow) == 1);  // taken from the samples
    }
    REQUIRE(s.samples.size() == doc.at("samples").size());
    for (std::size_t i = 0; i < s.samples.size(); ++i) {
        CHECK(s.samples[i].q == doc["samples"][i].at("q").get<std::vector<double>>());
        CHECK(s.samples[i].primitive == doc["samples"][i].at("primitive").get<int>());
    }
    CHECK(parsed.has_certificate == doc.contains("certificate"));
    if (!doc.contains("certificate")) return;
    const json& c = doc["certificate"];
    const auto& cert = s.certificate;
    CHECK(cert.min_clearance == number_or_infinity(c.at("min_clearance_margin")));
    CHECK(cert.min_self_clearance == number_or_infinity(c.at("min_self_collision_margin")));
    CHECK(cert.max_deviation == c.at("max_ee_deviation").get<double>());
    if (c.contains("max_joint_step"))
        CHECK(cert.max_joint_step == c["max_joint_step"].get<double>());
}

struct Counts {
    int tasks = 0;
    int solutions = 0;
};

/// Reads every JSON example of a document with modsynth's parsers.
Counts check_examples(const std::string& path, const std::vector<std::string>& lines) {
    Counts n;
    for (const Block& b : json_blocks(lines)) {
        INFO(path << ", the json block at line " << b.line);
        json doc;
        REQUIRE_NOTHROW(doc = json::parse(b.text));
        REQUIRE(doc.is_object());
        REQUIRE(doc.contains("format"));
        const std::string format = doc["format"].get<std::string>();
        try {
            if (format == "modsynth-task/1") {
                check_task_example(doc);
                ++n.tasks;
            } else if (format == "modsynth-solution/1") {
                check_solution_example(doc);
                ++n.solutions;
            } else if (format == "modsynth-catalog/1") {
                modsynth::hardware::Catalog catalog;
                REQUIRE_NOTHROW(modsynth::hardware::parse_catalog_file(b.text, path, catalog));
                CHECK(catalog.actuators.size() + catalog.tubes.size() + catalog.adapters.size() ==
                      doc.at("entries").size());
            } else {
                FAIL("an example of an unknown format: " << format);
            }
        } catch (const InputError& e) {
            FAIL("modsynth rejects the example: " << e.what());
        }
    }
    return n;
}

}  // namespace

TEST_CASE("docs/formats.md: every JSON example is read by modsynth's parsers", "[docs]") {
    std::vector<std::string> lines;
    REQUIRE(read_lines(kProjectFormats, lines));
    const Counts n = check_examples(kProjectFormats, lines);
    // The shared examples (one task, one solution) and the project's own
    // (a task with hardware sizes; solutions with a certificate, with a null
    // margin, and an infeasible one).
    CHECK(n.tasks >= 2);
    CHECK(n.solutions >= 4);
}

TEST_CASE("docs/formats.md: the project additions are marked and cover the extensions", "[docs]") {
    std::vector<std::string> lines;
    REQUIRE(read_lines(kProjectFormats, lines));
    std::ostringstream all;
    for (const auto& l : lines) all << l << '\n';
    const std::string text = all.str();
    CHECK(text.find("# Project additions (optional keys)") != std::string::npos);
    // Every optional key modsynth reads or writes beyond the shared contract.
    for (const char* key :
         {"`robot.module_length`", "`robot.module_width`", "`robot.module_height`",
          "`robot.adapter_length`", "`robot.ee_rod_diameter`", "`robot.elbow`",
          "`certificate.min_clearance_margin`", "`certificate.min_self_collision_margin`",
          "`certificate.max_ee_deviation`", "`certificate.max_joint_step`",
          "`explanation.separation`", "`explanation.geodesic`", "`strokes[s][j]`"}) {
        INFO(key);
        CHECK(text.find(key) != std::string::npos);
    }
}

TEST_CASE("docs/formats.md holds every line of the shared contract, in order", "[docs]") {
    const std::string shared_path = shared_formats_path();
    std::vector<std::string> shared, project;
    REQUIRE(read_lines(kProjectFormats, project));
    if (!read_lines(shared_path, shared)) {
        WARN("shared contract not found at " << shared_path << "; its checks are skipped");
        return;
    }
    REQUIRE(shared.size() > 20);
    std::size_t at = 0;
    for (std::size_t i = 0; i < shared.size(); ++i) {
        while (at < project.size() && project[at] != shared[i]) ++at;
        INFO("line " << i + 1 << " of " << shared_path << ": \"" << shared[i] << "\"");
        REQUIRE(at < project.size());
        ++at;
    }

    // The shared examples are read by modsynth too.
    const Counts n = check_examples(shared_path, shared);
    CHECK(n.tasks >= 1);
    CHECK(n.solutions >= 1);
}

// What docs/formats.md says of the extensions modsynth does not implement
// yet. When one is implemented, this fails: update the document with it.
TEST_CASE("docs/formats.md: the extensions not yet implemented behave as documented", "[docs]") {
    const json task = json::parse(R"({
        "format": "modsynth-task/1",
        "trajectory": [{"type": "line", "start": [0.4, 0.1], "end": [0.5, 0.1]}]
    })");

    SECTION(
        "a spatial task is read by the spatial reader only, a planar one with "
        "\"space\": \"plane\" by the planar one") {
        json doc = task;
        doc["space"] = "3d";
        try {
            parse_task(doc);
            FAIL("the planar reader read a spatial task");
        } catch (const InputError& e) {
            CHECK(e.part() == "space");
            CHECK(std::string(e.what()).find("not supported here yet") != std::string::npos);
        }
        doc["trajectory"][0] = {
            {"type", "line"}, {"start", {0.4, 0.1, 0.2}}, {"end", {0.5, 0.1, 0.2}}};
        CHECK(modsynth::io::parse_spatial_task(doc).trajectory.size() == 1);
        doc = task;
        doc["space"] = "plane";
        CHECK(parse_task(doc).trajectory.size() == 1);
        doc["space"] = "4d";
        CHECK_THROWS_AS(parse_task(doc), InputError);
    }
    SECTION("robot.joint_limits is not read") {
        json doc = task;
        doc["robot"] = {{"joint_limits", {{"velocity", 1.0}, {"acceleration", 2.0}}}};
        const modsynth::task::Task parsed = parse_task(doc);
        CHECK(parsed.trajectory.size() == 1);
    }
    SECTION("qd and qdd are not read") {
        json sol = json::parse(R"({
            "format": "modsynth-solution/1", "status": "solved",
            "robot": {"dof": 2, "base": [0, 0], "link_lengths": [0.3, 0.3], "link_diameter": 0.03},
            "samples": [{"t": 0, "phase": "trace", "primitive": 0, "q": [0.1, 1.0],
                         "qd": [0, 0], "qdd": [0, 0]}]
        })");
        CHECK(parse_solution(sol).solution.samples.size() == 1);
    }
}

// The extension "Several strokes", as docs/formats.md says modsynth reads it.
TEST_CASE("docs/formats.md: several strokes are read as documented", "[docs]") {
    const json line = json::parse(R"({"type": "line", "start": [0.4, 0.1], "end": [0.5, 0.1]})");
    const json other = json::parse(R"({"type": "line", "start": [0.4, 0.3], "end": [0.5, 0.3]})");
    json task = {{"format", "modsynth-task/1"}, {"strokes", {{line}, {other}}}};

    SECTION("a task with strokes names its primitives strokes[s][j]") {
        const modsynth::task::Task parsed = parse_task(task);
        REQUIRE(parsed.trajectory.size() == 2);
        CHECK(parsed.stroke_starts == std::vector<int>{0, 1});
    }
    SECTION("trajectory and strokes together are rejected") {
        task["trajectory"] = {line};
        try {
            parse_task(task);
            FAIL("a task with both trajectory and strokes was accepted");
        } catch (const InputError& e) {
            CHECK(e.part() == "strokes");
        }
    }
    SECTION("travel samples and stroke are read; a missing stroke is 0") {
        json sol = json::parse(R"({
            "format": "modsynth-solution/1", "status": "solved",
            "robot": {"dof": 2, "base": [0, 0], "link_lengths": [0.3, 0.3], "link_diameter": 0.03},
            "samples": [{"t": 0, "phase": "trace", "primitive": 0, "q": [0.1, 1.0]},
                        {"t": 1, "phase": "travel", "primitive": 0, "q": [0.1, 1.0], "stroke": 0},
                        {"t": 2, "phase": "trace", "primitive": 0, "q": [0.1, 1.0], "stroke": 1}]
        })");
        const auto samples = parse_solution(sol).solution.samples;
        REQUIRE(samples.size() == 3);
        CHECK(samples[0].stroke == 0);
        CHECK(samples[1].phase == modsynth::control::Phase::Travel);
        CHECK(samples[2].stroke == 1);
    }
}
