// Tasks of several strokes (formats.md "Several strokes"): the model, the
// names of their parts, and how the reader validates them.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <modsynth/io/task_io.h>
#include <modsynth/task/strokes.h>

using Catch::Matchers::Contains;
using modsynth::io::parse_task;
using modsynth::io::to_json;
using modsynth::task::InputError;
using modsynth::task::Task;
using nlohmann::json;
namespace task = modsynth::task;

namespace {

json line(double x0, double y0, double x1, double y1) {
    return {{"type", "line"}, {"start", {x0, y0}}, {"end", {x1, y1}}};
}

// Three strokes: two lines, one circle, one line.
json three_strokes() {
    return {{"format", "modsynth-task/1"},
            {"strokes",
             {{line(0.4, 0.1, 0.5, 0.1), line(0.5, 0.1, 0.5, 0.2)},
              {{{"type", "circle"},
                {"start", {0.45, 0.3}},
                {"center", {0.40, 0.3}},
                {"direction", "ccw"}}},
              {line(0.3, -0.2, 0.5, -0.2)}}}};
}

template <class F>
InputError input_error(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e;
    }
    FAIL("no InputError");
    throw;  // unreachable
}

}  // namespace

TEST_CASE("strokes: one list of primitives with the stroke boundaries", "[strokes]") {
    const Task t = parse_task(three_strokes());
    REQUIRE(t.trajectory.size() == 4);
    CHECK(t.stroke_starts == std::vector<int>{0, 2, 3});
    CHECK(task::has_strokes(t));
    CHECK(task::stroke_count(t) == 3);
    CHECK(task::stroke_first(t, 1) == 2);
    CHECK(task::stroke_last(t, 0) == 1);
    CHECK(task::stroke_last(t, 2) == 3);
    CHECK(task::stroke_of(t, 0) == 0);
    CHECK(task::stroke_of(t, 1) == 0);
    CHECK(task::stroke_of(t, 2) == 1);
    CHECK(task::stroke_of(t, 3) == 2);
    CHECK(task::index_in_stroke(t, 1) == 1);
    CHECK(task::index_in_stroke(t, 3) == 0);
    CHECK(task::primitive_index(t, 2, 0) == 3);
    // Transitions only inside a stroke.
    CHECK(task::has_transition_after(t, 0));
    CHECK_FALSE(task::has_transition_after(t, 1));
    CHECK_FALSE(task::has_transition_after(t, 2));
    CHECK_FALSE(task::has_transition_after(t, 3));
    CHECK(task::ends_stroke(t, 1));
    CHECK_FALSE(task::ends_stroke(t, 0));
}

TEST_CASE("strokes: parts are named strokes[s][j], a trajectory keeps trajectory[j]", "[strokes]") {
    const Task t = parse_task(three_strokes());
    CHECK(task::part_name(t, 0) == "strokes[0][0]");
    CHECK(task::part_name(t, 1) == "strokes[0][1]");
    CHECK(task::part_name(t, 2) == "strokes[1][0]");
    CHECK(task::part_name(t, 3) == "strokes[2][0]");
    using task::TaskPart;
    CHECK(TaskPart::primitive(t, 2) == TaskPart::stroke_primitive(1, 0));
    CHECK(task::primitive_index(t, TaskPart::stroke_primitive(1, 0)) == 2);
    CHECK(task::primitive_index(t, TaskPart::stroke_primitive(0, 1).with_field("end")) == 1);
    CHECK_FALSE(task::primitive_index(t, TaskPart::stroke_primitive(1, 1)));
    CHECK_FALSE(task::primitive_index(t, TaskPart::stroke_primitive(3, 0)));
    CHECK_FALSE(task::primitive_index(t, TaskPart::trajectory(0)));

    const Task one =
        parse_task({{"format", "modsynth-task/1"}, {"trajectory", {line(0.4, 0.1, 0.5, 0.1)}}});
    CHECK_FALSE(task::has_strokes(one));
    CHECK(task::stroke_count(one) == 1);
    CHECK(task::part_name(one, 0) == "trajectory[0]");
    CHECK(task::primitive_index(one, TaskPart::trajectory(0)) == 0);
    CHECK_FALSE(task::primitive_index(one, TaskPart::stroke_primitive(0, 0)));
    CHECK(task::has_transition_after(
        parse_task({{"format", "modsynth-task/1"},
                    {"trajectory", {line(0.4, 0.1, 0.5, 0.1), line(0.5, 0.1, 0.5, 0.2)}}}),
        0));
}

TEST_CASE("strokes: to_json writes strokes back and round-trips", "[strokes]") {
    const Task t = parse_task(three_strokes());
    const json doc = to_json(t);
    CHECK_FALSE(doc.contains("trajectory"));
    REQUIRE(doc["strokes"].size() == 3);
    CHECK(doc["strokes"][0].size() == 2);
    const Task back = parse_task(doc);
    CHECK(back.stroke_starts == t.stroke_starts);
    CHECK(back.trajectory.size() == t.trajectory.size());
    // A single stroke written with `strokes` stays `strokes`.
    json single = three_strokes();
    single["strokes"] = json::array({single["strokes"][0]});
    CHECK(to_json(parse_task(single)).contains("strokes"));
}

TEST_CASE("strokes: bad inputs are rejected naming the part", "[strokes]") {
    SECTION("both trajectory and strokes") {
        json doc = three_strokes();
        doc["trajectory"] = {line(0.4, 0.1, 0.5, 0.1)};
        const InputError e = input_error([&] { parse_task(doc); });
        CHECK(e.part() == "strokes");
        CHECK_THAT(e.what(), Contains("not both"));
    }
    SECTION("neither") {
        json doc = three_strokes();
        doc.erase("strokes");
        CHECK(input_error([&] { parse_task(doc); }).part() == "trajectory");
    }
    SECTION("no strokes") {
        json doc = three_strokes();
        doc["strokes"] = json::array();
        CHECK(input_error([&] { parse_task(doc); }).part() == "strokes");
    }
    SECTION("an empty stroke") {
        json doc = three_strokes();
        doc["strokes"][1] = json::array();
        const InputError e = input_error([&] { parse_task(doc); });
        CHECK(e.part() == "strokes[1]");
        CHECK_THAT(e.what(), Contains("empty"));
    }
    SECTION("a stroke that is not a list") {
        json doc = three_strokes();
        doc["strokes"][2] = line(0.3, -0.2, 0.5, -0.2);
        CHECK(input_error([&] { parse_task(doc); }).part() == "strokes[2]");
    }
    SECTION("a stroke that does not connect") {
        json doc = three_strokes();
        doc["strokes"][0][1] = line(0.5, 0.12, 0.5, 0.2);
        const InputError e = input_error([&] { parse_task(doc); });
        CHECK(e.part() == "strokes[0][1]");
        CHECK_THAT(e.what(), Contains("strokes[0][0]"));
    }
    SECTION("a bad primitive inside a stroke") {
        json doc = three_strokes();
        doc["strokes"][2][0]["type"] = "spline";
        CHECK(input_error([&] { parse_task(doc); }).part() == "strokes[2][0].type");
    }
    SECTION("an obstacle on a stroke") {
        json doc = three_strokes();
        doc["obstacles"] = {{{"center", {0.4, -0.2}}, {"radius", 0.01}}};
        const InputError e = input_error([&] { parse_task(doc); });
        CHECK(e.part() == "obstacles[0]");
        CHECK_THAT(e.what(), Contains("strokes[2][0]"));
    }
    SECTION("strokes need not connect to each other") {
        CHECK_NOTHROW(parse_task(three_strokes()));
    }
}
