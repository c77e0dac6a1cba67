#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include <nlohmann/json.hpp>

#include <modsynth/io/solution_io.h>
#include <modsynth/io/task_io.h>
#include <modsynth/output/build_sheet.h>
#include <modsynth/output/recertify.h>
#include <modsynth/output/report.h>

#include "../support/fixtures.h"

namespace testing = modsynth::testing;
using modsynth::io::ParsedSolution;
using modsynth::output::recertify;
using modsynth::output::uncertified_reason;

namespace {

// A solution `modsynth solve tasks/rose.json` wrote, kept as a fuzzing seed.
const char* const kRoseSolution = "tests/fuzz/corpus/solution/rose.json";

modsynth::task::Task rose() {
    return modsynth::io::load_task(testing::source_path("tasks/rose.json"));
}

nlohmann::json rose_solution() { return testing::read_json(testing::source_path(kRoseSolution)); }

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("a saved solution verifies again as certified", "[output][recertify]") {
    const auto task = rose();
    ParsedSolution parsed = modsynth::io::parse_solution(rose_solution());
    REQUIRE(parsed.has_certificate);
    CHECK(recertify(task, parsed).empty());
    CHECK(parsed.solution.certificate.ok);
    CHECK(uncertified_reason(parsed.solution.certificate).empty());
    CHECK_FALSE(has(modsynth::output::build_sheet(task, parsed.solution), "not certified"));
}

TEST_CASE("an edited motion is not certified, whatever certificate the file stores",
          "[output][recertify]") {
    const auto task = rose();
    nlohmann::json doc = rose_solution();
    // One joint angle changed: the EE leaves the path at sample 40.
    doc["samples"][40]["q"][0] = doc["samples"][40]["q"][0].get<double>() + 0.05;
    ParsedSolution parsed = modsynth::io::parse_solution(doc);
    REQUIRE(parsed.has_certificate);
    recertify(task, parsed);
    const auto& c = parsed.solution.certificate;
    CHECK_FALSE(c.ok);
    const bool off_path = std::any_of(c.violations.begin(), c.violations.end(), [](const auto& v) {
        return v.sample == 40 && v.kind == modsynth::verify::Violation::Kind::Deviation;
    });
    CHECK(off_path);
    const std::string reason = uncertified_reason(c);
    CHECK(reason.rfind("samples[40]: ", 0) == 0);
    CHECK(has(reason, " more)"));

    const std::string sheet = modsynth::output::build_sheet(task, parsed.solution);
    CHECK(has(sheet, "**Warning:** not certified: samples\\[40\\]\\: "));
    const std::string html = modsynth::output::html_report(task, parsed.solution, {});
    CHECK(has(html, "<strong>not certified</strong>: samples[40]: "));
    CHECK_FALSE(has(html, ">Certified "));
}

TEST_CASE("a pose moved into an obstacle is not certified", "[output][recertify]") {
    auto task = rose();
    ParsedSolution parsed = modsynth::io::parse_solution(rose_solution());
    // The motion unchanged, an obstacle grown over the arm's start pose.
    task.obstacles[2].radius = 0.2;
    recertify(task, parsed);
    CHECK_FALSE(parsed.solution.certificate.ok);
    CHECK(has(uncertified_reason(parsed.solution.certificate), "too close to obstacles[2]"));
}

TEST_CASE("a solution without a certificate is certified on import, and says so",
          "[output][recertify]") {
    const auto task = rose();
    nlohmann::json doc = rose_solution();
    doc.erase("certificate");
    ParsedSolution parsed = modsynth::io::parse_solution(doc);
    CHECK(has(recertify(task, parsed), "carries no certificate"));
    CHECK(parsed.solution.certificate.ok);
}

TEST_CASE("recertify rejects a solution of another task", "[output][recertify]") {
    auto task = rose();
    task.name = "tulip";
    ParsedSolution parsed = modsynth::io::parse_solution(rose_solution());
    CHECK_THROWS_AS(recertify(task, parsed), modsynth::task::InputError);
}
