#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>

#include <nlohmann/json.hpp>

#include <modsynth/io/solution_io.h>
#include <modsynth/task/limits.h>

#include "../output/output_fixtures.h"

using modsynth::io::parse_solution;
using modsynth::io::to_json;
using modsynth::synth::Solution;
using modsynth::synth::Status;
using modsynth::task::InputError;
using nlohmann::json;
namespace testing = modsynth::testing;

namespace {

/// The part named by the InputError `f` throws; fails when it throws none.
std::string rejected_part(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.part();
    }
    FAIL("no InputError thrown");
    return "";
}

std::string part_of(const json& doc) {
    return rejected_part([&] { parse_solution(doc); });
}

void check_same_motion(const Solution& a, const Solution& b) {
    REQUIRE(b.samples.size() == a.samples.size());
    for (std::size_t i = 0; i < a.samples.size(); ++i) {
        CHECK(b.samples[i].t == a.samples[i].t);
        CHECK(b.samples[i].phase == a.samples[i].phase);
        CHECK(b.samples[i].primitive == a.samples[i].primitive);
        CHECK(b.samples[i].q == a.samples[i].q);
    }
}

}  // namespace

TEST_CASE("the reader round-trips a solved solution exactly", "[output]") {
    for (const auto& task : {testing::two_joint_task(), testing::three_joint_task()}) {
        const Solution a = task.robot.dof[0] == 2 ? testing::two_joint_solution(task)
                                                  : testing::three_joint_solution(task);
        // Through text, as a saved file would be.
        const auto parsed = modsynth::io::parse_solution_text(to_json(a).dump(1));
        const Solution& b = parsed.solution;
        CHECK(parsed.has_certificate);
        CHECK(b.task_name == a.task_name);
        CHECK(b.status == Status::Solved);
        CHECK(b.robot.base == a.robot.base);
        CHECK(b.robot.link_lengths == a.robot.link_lengths);
        CHECK(b.robot.link_diameter == a.robot.link_diameter);
        CHECK(b.robot.elbow == a.robot.elbow);
        CHECK(b.certificate.ok);
        CHECK(b.certificate.min_clearance == a.certificate.min_clearance);
        CHECK(b.certificate.min_self_clearance == a.certificate.min_self_clearance);
        CHECK(b.certificate.max_deviation == a.certificate.max_deviation);
        check_same_motion(a, b);
        // And it writes back the same document.
        CHECK(to_json(b) == to_json(a));
    }
}

TEST_CASE("the reader round-trips an infeasible solution", "[output]") {
    const Solution a = testing::infeasible_solution(testing::two_joint_task());
    const Solution b = parse_solution(to_json(a)).solution;
    CHECK(b.status == Status::Infeasible);
    CHECK(b.explanation.message == a.explanation.message);
    CHECK(b.explanation.core == a.explanation.core);
    CHECK(to_json(b) == to_json(a));
}

TEST_CASE("the reader accepts solutions without elbow or certificate", "[output]") {
    const auto task = testing::two_joint_task();
    const Solution a = testing::two_joint_solution(task);
    json doc = to_json(a);
    doc["robot"].erase("elbow");
    doc.erase("certificate");
    const auto parsed = parse_solution(doc);
    CHECK_FALSE(parsed.has_certificate);
    CHECK_FALSE(parsed.solution.certificate.ok);
    // The branch is read off the motion: the last joint's sign.
    CHECK(parsed.solution.robot.elbow == a.robot.elbow);
    check_same_motion(a, parsed.solution);
}

TEST_CASE("null certificate margins mean nothing was there to check", "[output]") {
    const auto task = testing::two_joint_task();
    json doc = to_json(testing::two_joint_solution(task));
    doc["certificate"]["min_clearance_margin"] = nullptr;
    const auto parsed = parse_solution(doc);
    CHECK(std::isinf(parsed.solution.certificate.min_clearance));
}

TEST_CASE("the reader rejects bad solutions naming the part", "[output]") {
    const auto task = testing::two_joint_task();
    const json good = to_json(testing::two_joint_solution(task));
    json doc = good;

    SECTION("not an object") { CHECK(part_of(json::array()) == "(document)"); }
    SECTION("another format") {
        doc["format"] = "modsynth-task/1";
        CHECK(part_of(doc) == "format");
    }
    SECTION("unknown status") {
        doc["status"] = "done";
        CHECK(part_of(doc) == "status");
    }
    SECTION("solved without a robot") {
        doc.erase("robot");
        CHECK(part_of(doc) == "robot");
    }
    SECTION("unsupported joint count") {
        doc["robot"]["dof"] = 5;
        CHECK(part_of(doc) == "robot.dof");
    }
    SECTION("link lengths disagree with dof") {
        doc["robot"]["link_lengths"] = {0.3};
        CHECK(part_of(doc) == "robot.link_lengths");
    }
    SECTION("negative link length") {
        doc["robot"]["link_lengths"][1] = -0.3;
        CHECK(part_of(doc) == "robot.link_lengths[1]");
    }
    SECTION("elbow zero") {
        doc["robot"]["elbow"] = 0;
        CHECK(part_of(doc) == "robot.elbow");
    }
    SECTION("no samples") {
        doc["samples"] = json::array();
        CHECK(part_of(doc) == "samples");
    }
    SECTION("a joint angle missing") {
        doc["samples"][3]["q"] = {0.1};
        CHECK(part_of(doc) == "samples[3].q");
    }
    SECTION("a joint angle that is not a number") {
        doc["samples"][4]["q"][1] = "x";
        CHECK(part_of(doc) == "samples[4].q[1]");
    }
    SECTION("unknown phase") {
        doc["samples"][2]["phase"] = "hold";
        CHECK(part_of(doc) == "samples[2].phase");
    }
    SECTION("negative primitive") {
        doc["samples"][2]["primitive"] = -1;
        CHECK(part_of(doc) == "samples[2].primitive");
    }
    SECTION("time going backwards") {
        doc["samples"][5]["t"] = -1.0;
        CHECK(part_of(doc) == "samples[5].t");
    }
    SECTION("a broken certificate") {
        doc["certificate"]["max_ee_deviation"] = "small";
        CHECK(part_of(doc) == "certificate.max_ee_deviation");
    }
    SECTION("infeasible without explanation") {
        doc = {{"format", "modsynth-solution/1"}, {"status", "infeasible"}};
        CHECK(part_of(doc) == "explanation");
    }
    SECTION("a core part that is not text") {
        doc = {{"format", "modsynth-solution/1"},
               {"status", "infeasible"},
               {"explanation", {{"message", "no"}, {"core", {"trajectory[0]", 3}}}}};
        CHECK(part_of(doc) == "explanation.core[1]");
    }
}

TEST_CASE("the reader names the position of a JSON syntax error", "[output]") {
    try {
        modsynth::io::parse_solution_text("{\n  \"format\": ,\n}");
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(e.part() == "(document)");
        CHECK_THAT(e.what(), Catch::Matchers::Contains("line 2"));
    }
}

TEST_CASE("load_solution names an unreadable file", "[output]") {
    const std::string path = "/nonexistent/solution.json";
    CHECK(rejected_part([&] { modsynth::io::load_solution(path); }) == path);
}

TEST_CASE("a solution must fit the task it is exported with", "[output]") {
    const auto task = testing::two_joint_task();
    Solution s = testing::two_joint_solution(task);
    CHECK_NOTHROW(modsynth::io::check_solution_fits(task, s));
    Solution other = s;
    other.task_name = "rose";
    CHECK(rejected_part([&] { modsynth::io::check_solution_fits(task, other); }) == "task");
    s.samples.back().primitive = 7;
    const std::string part = "samples[" + std::to_string(s.samples.size() - 1) + "].primitive";
    CHECK(rejected_part([&] { modsynth::io::check_solution_fits(task, s); }) == part);
}

TEST_CASE("chosen modules are written with their loads and margins", "[output]") {
    const auto task = testing::two_joint_task();
    Solution s = testing::two_joint_solution(task);
    CHECK_FALSE(to_json(s).contains("modules"));  // nothing chosen, nothing written
    modsynth::hardware::ModuleSelection sel;
    s.modules = sel;  // not checked (no qd, qdd): not written either
    CHECK_FALSE(to_json(s).contains("modules"));
    sel.checked = true;
    sel.joints.resize(2);
    sel.joints[0].module = "X8-16";
    sel.joints[0].load.peak_torque = 41.5;
    sel.joints[0].peak_margin = -3.5;
    sel.joints[1].module = "X5-4";
    sel.joints[1].carries = true;
    sel.overloaded_joint = 1;
    sel.message = "joint 1 is overloaded";
    s.modules = sel;
    const json doc = to_json(s);
    CHECK(doc.at("status") == "solved");
    const json& m = doc.at("modules");
    CHECK(m.at("overloaded_joint") == 1);
    CHECK(m.at("joints")[0].at("module") == "X8-16");
    CHECK(m.at("joints")[0].at("peak_torque") == 41.5);
    CHECK(m.at("joints")[0].at("peak_torque_margin") == -3.5);
    CHECK(m.at("joints")[1].at("carries") == true);
    // Readers ignore the key: the motion reads back the same.
    check_same_motion(s, parse_solution(doc).solution);
    s.modules->overloaded_joint = 0;
    CHECK(to_json(s).at("modules").at("overloaded_joint").is_null());
}

TEST_CASE("a spatial solution's DH robot round-trips and is checked", "[io]") {
    const json doc =
        json::parse(R"({"format": "modsynth-solution/1", "task": "s", "status": "solved",
        "robot": {"dof": 3, "base": [0.1, -0.2, 0.05],
                  "dh": [{"a": 0, "alpha": 1.5707963267948966, "d": 0.4},
                         {"a": 0.3, "alpha": 0, "d": 0}, {"a": 0.25, "alpha": 0, "d": 0}],
                  "link_diameter": 0.03175},
        "samples": [{"t": 0, "phase": "trace", "primitive": 0, "q": [0.1, 0.2, 0.3]}]})");
    const Solution s = parse_solution(doc).solution;
    REQUIRE(s.dh_robot);
    CHECK(s.dh_robot->dof() == 3);
    CHECK(s.dh_robot->base.z() == 0.05);
    CHECK(s.dh_robot->rows[0].d == 0.4);
    CHECK(s.dh_robot->rows[2].a == 0.25);
    const json out = to_json(s);
    CHECK(out["robot"]["dh"].size() == 3);
    CHECK_FALSE(out["robot"].contains("link_lengths"));
    CHECK_FALSE(out["robot"].contains("elbow"));
    const Solution again = parse_solution(out).solution;
    CHECK(again.dh_robot->rows[1].a == 0.3);
    CHECK(again.dh_robot->base == s.dh_robot->base);
    check_same_motion(s, again);

    auto with = [&](const char* pointer, const json& value) {
        json d = doc;
        d[json::json_pointer(pointer)] = value;
        return d;
    };
    CHECK(part_of(with("/robot/dof", 2)) == "robot.dof");
    CHECK(part_of(with("/robot/base", json::array({0, 0}))) == "robot.base");
    CHECK(part_of(with("/robot/dh", json::array({json::object()}))) == "robot.dh");
    CHECK(part_of(with("/robot/dh/1/alpha", "flat")) == "robot.dh[1].alpha");
    CHECK(part_of(with("/robot/link_diameter", 0)) == "robot.link_diameter");
    CHECK(part_of(with("/samples/0/q", json::array({0.1, 0.2}))) == "samples[0].q");
}

TEST_CASE("a written solution file is the JSON document's text", "[output]") {
    // write_solution writes the samples without building a JSON value per
    // sample; the file must still be to_json(solution).dump(1), byte for byte.
    const auto task = testing::three_joint_task();
    Solution a = testing::three_joint_solution(task);
    REQUIRE(a.samples.size() >= 3);
    a.samples[0].qd = {0.0, -1.5, 2.0};
    a.samples[0].qdd = {1e-7, 3.0, -0.0};
    a.samples[1].qd = {std::nan(""), 1e300, -2.25};
    a.samples[1].stroke = 1;
    a.samples[2].phase = modsynth::control::Phase::Travel;
    a.samples[2].t = 1.0 / 3.0;
    const auto dir = std::filesystem::temp_directory_path() / "modsynth-solution-text-test";
    std::filesystem::create_directories(dir);
    for (const auto& s : {a, Solution{}}) {
        const std::string path = (dir / "solution.json").string();
        modsynth::io::write_solution(s, path);
        std::ifstream in(path, std::ios::binary);
        const std::string text((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
        CHECK(text == to_json(s).dump(1) + "\n");
    }
    std::filesystem::remove_all(dir);
}

TEST_CASE("a wall in space's witness round-trips, and a bad one is refused by name", "[output]") {
    Solution a;
    a.task_name = "walled";
    a.status = Status::Infeasible;
    a.explanation.message = "walled";
    modsynth::prove::Enclosure w;
    w.base_region = 0;
    w.primitive = 1;
    w.point = {0.6, 0.1, 0.2};
    w.obstacles = {0, 2, 5};
    w.grid = {{-0.3125, -0.25, 0.0}, 0.015625, {40, 30, 20}};
    w.base_inside = false;
    w.cells = {{3, 4, 5, 9}, {4, 4, 6, 6}};
    a.explanation.enclosure = modsynth::prove::EnclosureWitness{{w}};
    const json doc = to_json(a);
    const auto b = parse_solution(doc).solution.explanation.enclosure;
    REQUIRE(b);
    REQUIRE(b->walls.size() == 1);
    const auto& v = b->walls[0];
    CHECK(v.primitive == 1);
    CHECK(v.point == w.point);
    CHECK(v.obstacles == w.obstacles);
    CHECK(v.grid.origin == w.grid.origin);
    CHECK(v.grid.cell == w.grid.cell);
    CHECK(v.grid.size == w.grid.size);
    CHECK_FALSE(v.base_inside);
    REQUIRE(v.cells.size() == 2);
    CHECK(v.cells[0].i1 == 9);
    json bad = doc;
    bad["explanation"]["enclosure"]["walls"][0]["inside"] = "elsewhere";
    CHECK(part_of(bad) == "explanation.enclosure.walls[0].inside");
    bad = doc;
    bad["explanation"]["enclosure"]["walls"][0]["cells"][1] = json::array({1, 2});
    CHECK(part_of(bad) == "explanation.enclosure.walls[0].cells[1]");
}

TEST_CASE("a timed sample takes no more bytes in a file than task::max_sample_bytes", "[output]") {
    // Every number at its longest (24 characters), every index at 10
    // digits, a transition (the longest phase), strokes written.
    const double longest = -1.2345678901234567e-100;
    const auto dir = std::filesystem::temp_directory_path() / "modsynth-sample-bytes-test";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "solution.json").string();
    for (int dof = 1; dof <= 6; ++dof) {
        const auto file_size = [&](std::size_t count) {
            Solution s;
            s.task_name = "t";
            s.status = Status::Solved;
            s.robot.link_lengths.assign(static_cast<std::size_t>(dof), 0.5);
            modsynth::control::Sample x;
            x.t = longest;
            x.phase = modsynth::control::Phase::Transition;
            x.primitive = 2147483647;
            x.stroke = 2147483647;
            x.q.assign(static_cast<std::size_t>(dof), longest);
            x.qd = x.qdd = x.q;
            s.samples.assign(count, x);
            modsynth::io::write_solution(s, path);
            return std::filesystem::file_size(path);
        };
        const std::size_t per_sample = (file_size(101) - file_size(1)) / 100;
        CHECK(per_sample <= modsynth::task::max_sample_bytes(dof));
        // And the cap leaves a real motion room: hundreds of thousands.
        CHECK(modsynth::task::max_motion_samples(dof) >= 300000);
    }
    std::filesystem::remove_all(dir);
}

TEST_CASE("a solution is read a sample at a time, as a tree would read it", "[output]") {
    const auto task = testing::three_joint_task();
    const Solution a = testing::three_joint_solution(task);
    const json doc = to_json(a);
    // Samples before the robot, as another program may write them.
    std::string text = "{\"samples\": " + doc["samples"].dump() + ", ";
    for (const auto& [key, value] : doc.items())
        if (key != "samples") text += json(key).dump() + ": " + value.dump() + ", ";
    text.resize(text.size() - 2);
    text += "}";
    check_same_motion(a, modsynth::io::parse_solution_text(text).solution);
    // A key given twice: the later wins, as in the tree.
    json twice = doc;
    std::string doubled = twice.dump();
    doubled.insert(1, "\"samples\": [1, 2], ");
    check_same_motion(a, modsynth::io::parse_solution_text(doubled).solution);
    // A sample of another joint count, named once the robot is known.
    json wrong = doc;
    wrong["samples"][1]["q"] = json::array({0.1, 0.2});
    CHECK(rejected_part([&] { modsynth::io::parse_solution_text(wrong.dump()); }) ==
          "samples[1].q");
    // Samples of an unknown answer are not its motion: not read.
    json unknown = {{"format", "modsynth-solution/1"},
                    {"status", "unknown"},
                    {"explanation", {{"message", "gave up"}}},
                    {"samples", json::array({1, 2})}};
    CHECK(modsynth::io::parse_solution_text(unknown.dump()).solution.status == Status::Unknown);
    // From a file, streamed: the same solution, and syntax errors placed.
    const auto dir = std::filesystem::temp_directory_path() / "modsynth-stream-read-test";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "solution.json").string();
    modsynth::io::write_solution(a, path);
    check_same_motion(a, modsynth::io::load_solution(path).solution);
    std::ofstream(path) << "{\n \"format\": \"modsynth-solution/1\",\n \"status\": solved\n}\n";
    try {
        modsynth::io::load_solution(path);
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK_THAT(e.what(), Catch::Matchers::Contains("at line 3, column"));
    }
    std::filesystem::remove_all(dir);
}

TEST_CASE("a solution's robot lies within the task limits: no number of hundreds of digits",
          "[output]") {
    const auto task = testing::three_joint_task();
    const json doc = to_json(testing::three_joint_solution(task));
    json far = doc;
    far["robot"]["base"][0] = 1e308;
    CHECK(part_of(far) == "robot.base[0]");
    json long_link = doc;
    long_link["robot"]["link_lengths"][1] = 1e6;
    CHECK(part_of(long_link) == "robot.link_lengths[1]");
}
