#include <catch2/catch.hpp>

#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include <modsynth/io/task_checks.h>
#include <modsynth/io/task_document.h>
#include <modsynth/io/task_io.h>

#include "../support/fixtures.h"

using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using modsynth::io::nearest_word;
using modsynth::io::unit_warnings;
using modsynth::io::unknown_keys;
using modsynth::task::InputError;
using nlohmann::json;

namespace {

json rose() {
    std::ifstream in(modsynth::testing::source_path("tasks/rose.json"));
    return json::parse(in);
}

}  // namespace

TEST_CASE("a misspelt key is named with the key it most likely meant", "[io][checks]") {
    json doc = rose();
    doc["base_region"] = doc["base_regions"];
    doc.erase("base_regions");
    doc["robot"]["max_link_lenght"] = 0.8;
    doc["trajectory"][2]["centre"] = doc["trajectory"][2]["center"];
    doc["obstacles"][1]["radious"] = 0.05;
    doc["colour"] = "red";
    const auto warnings = unknown_keys(doc);
    REQUIRE(warnings.size() == 5);
    std::vector<std::string> parts;
    for (const auto& w : warnings) parts.push_back(w.part());
    CHECK(std::find(parts.begin(), parts.end(), "base_region") != parts.end());
    for (const auto& w : warnings) {
        if (w.part() == "base_region")
            CHECK(w.problem() == "not a key of a task; did you mean \"base_regions\"?");
        if (w.part() == "robot.max_link_lenght")
            CHECK_THAT(w.problem(), Contains("did you mean \"max_link_length\"?"));
        if (w.part() == "trajectory[2].centre")
            CHECK_THAT(w.problem(), Contains("did you mean \"center\"?"));
        if (w.part() == "obstacles[1].radious") CHECK_THAT(w.problem(), Contains("\"radius\""));
        if (w.part() == "colour")
            CHECK_THAT(w.problem(), Contains("docs/formats.md lists the keys"));
    }
    // The task as shipped has none; nor have the spatial examples, or a
    // task with the format's optional keys.
    CHECK(unknown_keys(rose()).empty());
    for (const char* name : {"tasks/spatial/helix-pipe.json", "tasks/spatial/glue-box-edges.json",
                             "tasks/rose-dynamixel.json", "tasks/strokes-two-circles.json"}) {
        std::ifstream in(modsynth::testing::source_path(name));
        CHECK(unknown_keys(json::parse(in)).empty());
    }
}

TEST_CASE("the nearest key is offered only for a slip, not for any word", "[io][checks]") {
    const std::vector<std::string> known = {"base_regions", "obstacles", "trajectory", "robot"};
    CHECK(nearest_word("base_region", known) == "base_regions");
    CHECK(nearest_word("Obstacles", known) == "obstacles");
    CHECK(nearest_word("trajetcory", known) == "trajectory");  // two letters swapped
    CHECK(nearest_word("colour", known).empty());
    CHECK(nearest_word("", known).empty());
}

TEST_CASE("a task in millimetres is named as such, once per kind of part", "[io][checks]") {
    json doc = rose();
    CHECK(unit_warnings(doc).empty());
    for (auto& p : doc["trajectory"])
        for (const char* k : {"start", "end", "center"})
            if (p.contains(k))
                p[k] = {p[k][0].get<double>() * 1000.0, p[k][1].get<double>() * 1000.0};
    doc["robot"]["max_link_length"] = 1000.0;
    const auto warnings = unit_warnings(doc);
    REQUIRE(warnings.size() == 2);
    CHECK_THAT(warnings[0].part(), StartsWith("trajectory["));
    CHECK_THAT(warnings[0].problem(), Contains("m from the origin"));
    CHECK_THAT(warnings[0].problem(), Contains("is the task in millimetres?"));
    CHECK(warnings[1].part() == "robot.max_link_length");
    CHECK_THAT(warnings[1].problem(), Contains("1000 m"));
    // A workcell 15 m across is not taken for millimetres.
    json big = rose();
    big["obstacles"][0]["center"] = {15.0, 5.0};
    CHECK(unit_warnings(big).empty());
}

TEST_CASE("an error is said of its file once, without the document's placeholder", "[io][checks]") {
    const InputError in_part("trajectory[1]", "arc end is 0.050 m farther from center than start");
    CHECK(std::string(in_part.in_file("task.json").what()) ==
          "task.json: trajectory[1]: arc end is 0.050 m farther from center than start");
    CHECK(in_part.in_file("task.json").part() == "trajectory[1]");
    CHECK(std::string(InputError("(document)", "not valid JSON").in_file("t.json").what()) ==
          "t.json: not valid JSON");
    CHECK(std::string(InputError("drawing.svg", "is a folder").in_file("drawing.svg").what()) ==
          "drawing.svg: is a folder");
    CHECK(std::string(InputError("--text", "no glyph for 'x'").in_file("--text").what()) ==
          "--text: no glyph for 'x'");
    // Said of a file once: a second file does not stack.
    CHECK(std::string(in_part.in_file("a.json").in_file("b.json").what()) ==
          "a.json: trajectory[1]: arc end is 0.050 m farther from center than start");
}

TEST_CASE("a task file's errors and warnings name the file", "[io][checks]") {
    const std::string path =
        modsynth::testing::source_path("tests/fixtures/mistakes/cut-short.json");
    try {
        modsynth::io::load_task_document(path);
        FAIL("a file cut short was read");
    } catch (const InputError& e) {
        CHECK_THAT(e.what(), StartsWith(path + ": not valid JSON at line 4"));
        CHECK(e.file() == path);
    }
    modsynth::io::TaskWarnings warnings;
    const std::string typo =
        modsynth::testing::source_path("tests/fixtures/mistakes/base-region-typo.json");
    modsynth::io::load_task_document(typo, warnings);
    REQUIRE(warnings.unknown_keys.size() == 1);
    CHECK_THAT(warnings.unknown_keys[0].what(), StartsWith(typo + ": base_region: "));
    CHECK(warnings.units.empty());
    CHECK_THROWS_WITH(modsynth::io::load_task(path), StartsWith(path + ": not valid JSON"));
}
