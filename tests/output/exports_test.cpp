#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <modsynth/output/build_sheet.h>
#include <modsynth/output/csv.h>
#include <modsynth/output/exports.h>
#include <modsynth/output/urdf.h>

#include "output_fixtures.h"

namespace testing = modsynth::testing;
using modsynth::output::ExportPaths;
using modsynth::output::write_exports;

namespace {

std::string read(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

ExportPaths paths_in(const std::filesystem::path& dir) {
    return {(dir / "r.html").string(), (dir / "r.urdf").string(), (dir / "r.csv").string(),
            (dir / "r.md").string()};
}

}  // namespace

TEST_CASE("write_exports writes every wanted output of a solved solution", "[output]") {
    const auto task = testing::two_joint_task();
    const auto s = testing::two_joint_solution(task);
    const auto dir = testing::scratch_dir("exports");
    const ExportPaths paths = paths_in(dir);
    CHECK(write_exports(task, s, paths, {}).empty());
    CHECK(read(paths.urdf) == modsynth::output::robot_urdf(task, s));
    CHECK(read(paths.csv) == modsynth::output::trajectory_csv(s));
    CHECK(read(paths.build_sheet) == modsynth::output::build_sheet(task, s));
    CHECK(read(paths.report) == modsynth::output::html_report(task, s, {}));
}

TEST_CASE("write_exports writes only what is asked for", "[output]") {
    const auto task = testing::two_joint_task();
    const auto dir = testing::scratch_dir("exports_some");
    ExportPaths paths;
    CHECK_FALSE(paths.any());
    paths.csv = (dir / "only.csv").string();
    CHECK(paths.any());
    CHECK(write_exports(task, testing::two_joint_solution(task), paths, {}).empty());
    CHECK(std::distance(std::filesystem::directory_iterator(dir), {}) == 1);
}

TEST_CASE("an unsolved solution gets a report but no robot outputs", "[output]") {
    const auto task = testing::two_joint_task();
    const auto dir = testing::scratch_dir("exports_infeasible");
    const ExportPaths paths = paths_in(dir);
    const auto skipped = write_exports(task, testing::infeasible_solution(task), paths, {});
    REQUIRE(skipped.size() == 3);
    CHECK(skipped[0].rfind("--urdf ", 0) == 0);
    CHECK(skipped[1].rfind("--csv ", 0) == 0);
    CHECK(skipped[2].rfind("--build-sheet ", 0) == 0);
    CHECK(std::filesystem::file_size(paths.report) > 0);
    CHECK_FALSE(std::filesystem::exists(paths.urdf));
    CHECK_FALSE(std::filesystem::exists(paths.csv));
    CHECK_FALSE(std::filesystem::exists(paths.build_sheet));
}

TEST_CASE("an unwritable output path is an error naming it", "[output]") {
    const auto task = testing::two_joint_task();
    ExportPaths paths;
    paths.csv = "/nonexistent/dir/x.csv";
    try {
        write_exports(task, testing::two_joint_solution(task), paths, {});
        FAIL("no error");
    } catch (const std::runtime_error& e) {
        CHECK_THAT(e.what(), Catch::Matchers::Contains("/nonexistent/dir/x.csv"));
    }
}
