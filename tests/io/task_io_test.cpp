#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include <nlohmann/json.hpp>

#include <modsynth/io/task_io.h>
#include <modsynth/task/limits.h>
#include <modsynth/text/printable.h>

using Catch::Matchers::Contains;
using modsynth::geometry::kPi;
using modsynth::geometry::PrimitiveKind;
using modsynth::io::load_task;
using modsynth::io::parse_task;
using modsynth::io::parse_task_text;
using modsynth::io::to_json;
using modsynth::task::InputError;
using modsynth::task::Task;
using nlohmann::json;

namespace {

const std::string kFixtures = std::string(MODSYNTH_SOURCE_DIR) + "/tests/fixtures/";

json read_json(const std::string& path) {
    std::ifstream in(path);
    REQUIRE(in);
    return json::parse(in);
}

/// The InputError `f` throws; fails the test if it throws nothing.
template <class F>
InputError input_error(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e;
    }
    FAIL("no InputError thrown");
    return InputError("", "");
}

json minimal_doc() {
    return json::parse(R"({"format": "modsynth-task/1",
        "trajectory": [{"type": "line", "start": [0.4, 0.1], "end": [0.55, 0.1]}]})");
}

}  // namespace

TEST_CASE("every invalid fixture is rejected naming its part", "[task]") {
    const std::string dir = kFixtures + "invalid/";
    const json expected = read_json(dir + "expected.json");
    REQUIRE(expected.size() >= 20);
    for (const auto& [file, want] : expected.items()) {
        SECTION(file) {
            const InputError e = input_error([&] { modsynth::io::load_task(dir + file); });
            CHECK(e.part() == want.at("part").get<std::string>());
            CHECK_THAT(e.what(), Contains(want.at("message_contains").get<std::string>()));
            // what() is "FILE: PART: problem" so a user sees where to look.
            CHECK(e.file() == dir + file);
            // (The whole document is named by its file alone.)
            const std::string where = e.part() == "(document)" ? "" : e.part() + ": ";
            CHECK_THAT(e.what(), Catch::Matchers::StartsWith(e.file() + ": " + where));
            // Messages are short, printable UTF-8 and say things once,
            // whatever bytes or numbers the task holds.
            const std::string what = e.what();
            CHECK(what.size() < 400);
            CHECK(modsynth::text::printable(what, what.size()) == what);
            CHECK_THAT(what, !Contains("expected expected"));
        }
    }
}

TEST_CASE("every invalid fixture is listed in expected.json", "[task]") {
    const std::string dir = kFixtures + "invalid/";
    const json expected = read_json(dir + "expected.json");
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (name == "expected.json") continue;
        INFO(name);
        CHECK(expected.contains(name));
    }
}

TEST_CASE("absent optional keys take the documented defaults", "[task]") {
    const Task t = modsynth::io::load_task(kFixtures + "valid/minimal.json");
    CHECK(t.name == "minimal");  // the file stem when the document has no name
    REQUIRE(t.trajectory.size() == 1);
    CHECK(t.trajectory[0].kind == PrimitiveKind::Line);
    CHECK(t.obstacles.empty());
    CHECK(t.base_regions.empty());
    CHECK(t.robot.dof == std::vector<int>{2, 3});
    CHECK(t.robot.link_diameter == Approx(0.03175));
    CHECK(t.robot.min_link_length == Approx(0.05));
    CHECK(t.robot.max_link_length == Approx(1.0));
    CHECK(modsynth::io::parse_task(minimal_doc()).name.empty());
}

TEST_CASE("a task with every key parses with the right geometry", "[task]") {
    const Task t = modsynth::io::load_task(kFixtures + "valid/full.json");
    CHECK(t.name == "rose");
    REQUIRE(t.trajectory.size() == 3);
    const auto& arc = t.trajectory[1];
    CHECK(arc.kind == PrimitiveKind::Arc);
    CHECK(arc.radius == Approx(0.05));
    CHECK(arc.sweep == Approx(kPi));  // ccw half turn on the right-hand side
    CHECK(arc.start_angle == Approx(-kPi / 2));
    const auto& circle = t.trajectory[2];
    CHECK(circle.kind == PrimitiveKind::Circle);
    CHECK(circle.sweep == Approx(-2 * kPi));
    CHECK(circle.radius == Approx(0.05));
    CHECK((circle.end - circle.start).norm() < 1e-12);
    REQUIRE(t.obstacles.size() == 1);
    CHECK(t.obstacles[0].radius == Approx(0.05));
    REQUIRE(t.base_regions.size() == 2);
    CHECK(t.base_regions[0].contains({0.0, 0.0}));
    CHECK(t.robot.dof == std::vector<int>{2, 3});  // stored sorted
    CHECK(t.robot.link_diameter == Approx(0.02));
    CHECK(t.robot.min_link_length == Approx(0.1));
    CHECK(t.robot.max_link_length == Approx(0.6));
}

TEST_CASE("an arc whose start equals its end is a full circle", "[task]") {
    const Task t = modsynth::io::load_task(kFixtures + "valid/full-circle-arc.json");
    REQUIRE(t.trajectory.size() == 2);
    CHECK(t.trajectory[0].sweep == Approx(-2 * kPi));
    CHECK(t.trajectory[0].radius == Approx(0.1));
}

TEST_CASE("clockwise arcs sweep negatively by the angle they cover", "[task]") {
    const Task t = modsynth::io::load_task(kFixtures + "valid/cw-quarter-arc.json");
    REQUIRE(t.trajectory.size() == 2);
    CHECK(t.trajectory[0].sweep == Approx(-kPi / 2));
    CHECK(t.trajectory[1].sweep == Approx(-3 * kPi / 2));
}

TEST_CASE("unknown keys are ignored for forward compatibility", "[task]") {
    const Task t = modsynth::io::load_task(kFixtures + "valid/unknown-keys.json");
    CHECK(t.trajectory.size() == 1);
    CHECK(t.robot.dof == std::vector<int>{2});
}

TEST_CASE("to_json round-trips through parse_task", "[task]") {
    for (const char* file :
         {"full.json", "full-circle-arc.json", "cw-quarter-arc.json", "minimal.json"}) {
        SECTION(file) {
            const Task a = modsynth::io::load_task(kFixtures + "valid/" + file);
            const json doc = modsynth::io::to_json(a);
            CHECK(doc.at("format") == "modsynth-task/1");
            // Through text too, as another tool would read it.
            const Task b = modsynth::io::parse_task_text(doc.dump());
            CHECK(b.name == a.name);
            REQUIRE(b.trajectory.size() == a.trajectory.size());
            for (std::size_t j = 0; j < a.trajectory.size(); ++j) {
                const auto& p = a.trajectory[j];
                const auto& q = b.trajectory[j];
                CHECK(p.kind == q.kind);
                CHECK((p.start - q.start).norm() < 1e-12);
                CHECK((p.end - q.end).norm() < 1e-12);
                CHECK((p.center - q.center).norm() < 1e-12);
                CHECK(p.radius == Approx(q.radius));
                CHECK(p.sweep == Approx(q.sweep));
            }
            REQUIRE(b.obstacles.size() == a.obstacles.size());
            for (std::size_t i = 0; i < a.obstacles.size(); ++i) {
                CHECK(b.obstacles[i].center == a.obstacles[i].center);
                CHECK(b.obstacles[i].radius == a.obstacles[i].radius);
            }
            REQUIRE(b.base_regions.size() == a.base_regions.size());
            for (std::size_t i = 0; i < a.base_regions.size(); ++i) {
                CHECK(b.base_regions[i].min == a.base_regions[i].min);
                CHECK(b.base_regions[i].max == a.base_regions[i].max);
            }
            CHECK(b.robot.dof == a.robot.dof);
            CHECK(b.robot.link_diameter == a.robot.link_diameter);
            CHECK(b.robot.min_link_length == a.robot.min_link_length);
            CHECK(b.robot.max_link_length == a.robot.max_link_length);
        }
    }
}

TEST_CASE("non-finite numbers built in code are rejected", "[task]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    SECTION("a point coordinate") {
        json doc = minimal_doc();
        doc["trajectory"][0]["end"][1] = nan;
        const InputError e = input_error([&] { modsynth::io::parse_task(doc); });
        CHECK(e.part() == "trajectory[0].end");
        CHECK_THAT(e.what(), Contains("NaN"));
    }
    SECTION("an obstacle radius") {
        json doc = minimal_doc();
        doc["obstacles"] = json::array({{{"center", {0.0, 0.5}}, {"radius", inf}}});
        const InputError e = input_error([&] { modsynth::io::parse_task(doc); });
        CHECK(e.part() == "obstacles[0].radius");
        CHECK_THAT(e.what(), Contains("finite"));
    }
    SECTION("a robot length") {
        json doc = minimal_doc();
        doc["robot"] = {{"max_link_length", -inf}};
        const InputError e = input_error([&] { modsynth::io::parse_task(doc); });
        CHECK(e.part() == "robot.max_link_length");
    }
    SECTION("a circle radius") {
        json doc = minimal_doc();
        doc["trajectory"].push_back({{"type", "circle"},
                                     {"start", {0.55, 0.1}},
                                     {"center", {0.55, 0.2}},
                                     {"direction", "ccw"},
                                     {"radius", nan}});
        const InputError e = input_error([&] { modsynth::io::parse_task(doc); });
        CHECK(e.part() == "trajectory[1].radius");
    }
}

TEST_CASE("syntax errors name the line and column", "[task]") {
    SECTION("a missing comma") {
        const std::string text = "{\n  \"format\": \"modsynth-task/1\"\n  \"trajectory\": []\n}";
        const InputError e = input_error([&] { modsynth::io::parse_task_text(text); });
        CHECK_THAT(e.what(), Contains("line 3, column 14"));
    }
    SECTION("a bad literal on the first line") {
        const InputError e = input_error([&] { modsynth::io::parse_task_text("{\"a\": tru}"); });
        CHECK_THAT(e.what(), Contains("line 1, column"));
    }
    SECTION("truncated text") {
        const InputError e = input_error([&] { modsynth::io::parse_task_text("{\n\"format\": "); });
        CHECK_THAT(e.what(), Contains("line 2"));
    }
    SECTION("empty text") {
        const InputError e = input_error([&] { modsynth::io::parse_task_text(""); });
        CHECK_THAT(e.what(), Contains("line 1, column 1"));
    }
}

TEST_CASE("a tiny but rejected gap is not printed as zero", "[task]") {
    json doc = minimal_doc();
    doc["trajectory"].push_back(
        {{"type", "line"}, {"start", {0.55, 0.100002}}, {"end", {0.6, 0.1}}});
    const InputError e = input_error([&] { modsynth::io::parse_task(doc); });
    CHECK(e.part() == "trajectory[1]");
    CHECK_THAT(e.what(), Contains("starts 0.000002 m from the end of trajectory[0]"));
}

TEST_CASE("gaps within the join tolerance are accepted", "[task]") {
    json doc = minimal_doc();
    doc["trajectory"].push_back(
        {{"type", "line"}, {"start", {0.55, 0.1000005}}, {"end", {0.6, 0.1}}});
    CHECK(modsynth::io::parse_task(doc).trajectory.size() == 2);
}

TEST_CASE("dof accepts whole numbers written as decimals", "[task]") {
    json doc = minimal_doc();
    doc["robot"] = {{"dof", {3.0}}};
    CHECK(modsynth::io::parse_task(doc).robot.dof == std::vector<int>{3});
    doc["robot"] = {{"dof", {true}}};
    CHECK(input_error([&] { modsynth::io::parse_task(doc); }).part() == "robot.dof[0]");
}

TEST_CASE("an unreadable task file names the path", "[task]") {
    const std::string path = kFixtures + "valid/does-not-exist.json";
    const InputError e = input_error([&] { modsynth::io::load_task(path); });
    CHECK(e.part() == path);
    CHECK_THAT(e.what(), Contains("cannot open"));
    const InputError d = input_error([&] { modsynth::io::load_task(kFixtures + "valid"); });
    CHECK_THAT(d.what(), Contains("folder"));
}

TEST_CASE("tasks past the documented caps are rejected naming the part and the cap", "[task]") {
    using namespace modsynth::task;
    SECTION("primitives") {
        json doc = minimal_doc();
        json line = doc["trajectory"][0];
        for (std::size_t i = 0; i < kMaxPrimitives; ++i) {
            // Back and forth along one segment: connected, and any count.
            std::swap(line["start"], line["end"]);
            doc["trajectory"].push_back(line);
        }
        const InputError e = input_error([&] { parse_task(doc); });
        CHECK(e.part() == "trajectory");
        CHECK_THAT(e.what(), Contains("5001 primitives, more than the 5000 allowed"));
        doc["trajectory"].erase(doc["trajectory"].size() - 1);
        CHECK(parse_task(doc).trajectory.size() == kMaxPrimitives);
    }
    SECTION("obstacles") {
        json doc = minimal_doc();
        doc["obstacles"] = json::array();
        for (std::size_t i = 0; i <= kMaxObstacles; ++i)
            doc["obstacles"].push_back({{"center", {-0.5, 0.001 * i}}, {"radius", 0.0001}});
        const InputError e = input_error([&] { parse_task(doc); });
        CHECK(e.part() == "obstacles");
        CHECK_THAT(e.what(), Contains("1001 obstacles, more than the 1000 allowed"));
    }
    SECTION("coordinates and sizes") {
        json doc = minimal_doc();
        doc["trajectory"][0]["end"] = {1000.0, 0.1};
        CHECK_NOTHROW(parse_task(doc));
        doc["trajectory"][0]["end"] = {1000.5, 0.1};
        CHECK(input_error([&] { parse_task(doc); }).part() == "trajectory[0].end");
        doc = minimal_doc();
        doc["obstacles"] = {{{"center", {-5.0, 0.0}}, {"radius", 1e4}}};
        CHECK(input_error([&] { parse_task(doc); }).part() == "obstacles[0].radius");
    }
    SECTION("file size") {
        const std::string big(kMaxTaskBytes + 1, ' ');
        const InputError e = input_error([&] { parse_task_text(big); });
        CHECK(e.part() == "(document)");
        CHECK_THAT(e.what(), Contains("allowed for a task"));
    }
}

TEST_CASE("echoed text is printable and cut short", "[task]") {
    using modsynth::text::printable;
    CHECK(printable("ab\xff\x01"
                    "c") == "ab\\xFF\\x01c");
    CHECK(printable("caf\xc3\xa9") == "caf\xc3\xa9");  // valid UTF-8 stays
    CHECK(printable("\xc3") == "\\xC3");               // a cut sequence does not
    CHECK(printable(std::string(100, 'x'), 10) == std::string(10, 'x') + "...");
    CHECK(modsynth::text::compact(1e308) == "1e+308");
}

TEST_CASE("modules, payload and gravity are read, defaulted and written back", "[task]") {
    const Task plain = parse_task(minimal_doc());
    CHECK(plain.robot.modules.empty());
    CHECK(plain.robot.payload == 0.0);
    CHECK_FALSE(plain.robot.gravity.has_value());  // along the joint axes
    // A task without the keys is written without them.
    CHECK_FALSE(to_json(plain).at("robot").contains("modules"));
    CHECK_FALSE(to_json(plain).at("robot").contains("gravity"));

    json doc = minimal_doc();
    doc["robot"] = {{"modules", {"X8-9", "X5-4"}}, {"payload", 0.25}, {"gravity", {0.0, -9.81}}};
    const Task t = parse_task(doc);
    CHECK(t.robot.modules == std::vector<std::string>{"X8-9", "X5-4"});
    CHECK(t.robot.payload == 0.25);
    REQUIRE(t.robot.gravity.has_value());
    CHECK(t.robot.gravity->y() == -9.81);
    const Task back = parse_task_text(to_json(t).dump());
    CHECK(back.robot.modules == t.robot.modules);
    CHECK(back.robot.payload == t.robot.payload);
    CHECK(back.robot.gravity == t.robot.gravity);

    doc["robot"]["gravity"] = "joint_axes";
    CHECK_FALSE(parse_task(doc).robot.gravity.has_value());
}
