#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <modsynth/baseline/comparison.h>
#include <modsynth/io/task_io.h>
#include <modsynth/output/baseline_io.h>
#include <modsynth/output/report.h>

#include "../support/fixtures.h"

using namespace modsynth;

// The paper's finding (IV-B, Fig. 6) on its own "paint a rose" task: a robot
// designed from 25 points of the curve reaches them all, but the motion
// that connects them does not follow the curve, while modsynth's does.
TEST_CASE("on the rose, the discretized design strays from the curve and modsynth does not",
          "[baseline]") {
    const task::Task rose = io::load_task(testing::source_path("tasks/rose.json"));
    const baseline::Comparison c = baseline::compare_methods(rose, {}, {});
    REQUIRE(c.solution.status == synth::Status::Solved);
    REQUIRE(c.fidelity);
    REQUIRE(c.baseline.status == baseline::BaselineResult::Status::Executed);
    CHECK(c.baseline.design.robot.dof() == 2);
    CHECK(c.fidelity->max_deviation < 1e-3);
    CHECK(c.fidelity->whole_path_reachable());
    CHECK(c.baseline.fidelity.max_deviation > 5e-3);
    CHECK(c.baseline.fidelity.coverage_gap > 5e-3);

    const nlohmann::json doc = output::to_json(c);
    CHECK(doc["format"] == "modsynth-comparison/1");
    CHECK(doc["baseline_over_modsynth"]["max_ee_deviation"].get<double>() > 5.0);
    CHECK(doc["discretized"]["points"].size() == 25);

    output::ReportFigures figures;
    figures.comparison = &c;
    const std::string html = output::html_report(rose, c.solution, figures);
    CHECK(html.find("id=\"baseline\"") != std::string::npos);
    CHECK(html.find("id=\"comparison\"") != std::string::npos);
    CHECK(html.find("baseline-trail") != std::string::npos);
}

// With fewer points the design also leaves part of the curve outside its
// reachable space (Fig. 6A/B): the farthest part of the top circle falls
// between the points.
TEST_CASE("on the rose, a design from 12 points cannot reach the whole curve", "[baseline]") {
    const task::Task rose = io::load_task(testing::source_path("tasks/rose.json"));
    baseline::BaselineOptions o;
    o.points = 12;
    const baseline::BaselineResult r = baseline::run_baseline(rose, o);
    REQUIRE(r.design.found);
    CHECK_FALSE(r.fidelity.whole_path_reachable());
    CHECK(r.fidelity.outside_length > 0.01);
}
