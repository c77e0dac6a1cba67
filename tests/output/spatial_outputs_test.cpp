// The outputs of spatial solutions: the 3-D report, the DH arm's URDF and
// build sheet, and the CSV and ROS 2 joint trajectory for 3 to 6 joints;
// written together by write_exports as solve and export do.
#include <catch2/catch.hpp>

#include <modsynth/task/part.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <modsynth/control/path_corners.h>
#include <modsynth/control/spatial_samples.h>
#include <modsynth/geometry/primitive3.h>
#include <modsynth/hardware/catalog.h>
#include <modsynth/hardware/dh_stack.h>
#include <modsynth/hardware/select_dh_modules.h>
#include <modsynth/output/csv.h>
#include <modsynth/output/dh_build_sheet.h>
#include <modsynth/output/dh_urdf.h>
#include <modsynth/output/exports.h>
#include <modsynth/output/joint_trajectory.h>
#include <modsynth/output/report3d.h>
#include <modsynth/synth/spatial_module_choice.h>
#include <modsynth/text/format.h>
#include <modsynth/text/markdown.h>

#include "output_fixtures.h"
#include "spatial_fixtures.h"

using namespace modsynth;
namespace fs = std::filesystem;

namespace {

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

int count(const std::string& text, const std::string& pattern) {
    const std::regex re(pattern);
    return static_cast<int>(
        std::distance(std::sregex_iterator(text.begin(), text.end(), re), std::sregex_iterator()));
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream in(text);
    std::string line;
    while (std::getline(in, line)) out.push_back(line);
    return out;
}

std::string read(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

nlohmann::json scene_data(const std::string& html) {
    const std::string open = "<script type=\"application/json\" id=\"scene-data\">";
    const auto from = html.find(open);
    REQUIRE(from != std::string::npos);
    const auto to = html.find("</script>", from);
    return nlohmann::json::parse(html.substr(from + open.size(), to - from - open.size()));
}

/// Nothing is loaded from elsewhere when the file is viewed: no element
/// that fetches, and the only URLs are XML namespace names three.js passes
/// to createElementNS.
void check_self_contained(const std::string& html) {
    CHECK(html.rfind("<!DOCTYPE html>", 0) == 0);
    CHECK_FALSE(has(html, " src="));
    CHECK_FALSE(has(html, "<link"));
    CHECK_FALSE(has(html, "<iframe"));
    CHECK_FALSE(has(html, "@import"));
    const std::regex url("https?://[^\"' )]*");
    for (auto it = std::sregex_iterator(html.begin(), html.end(), url);
         it != std::sregex_iterator(); ++it)
        CHECK(it->str().rfind("http://www.w3.org/", 0) == 0);
    // One inline script for the view, one for its data; the script holds
    // three.js itself.
    CHECK(count(html, "<script[ >]") == 2);
    CHECK(has(html, "WebGLRenderer"));
    CHECK(has(html, "</html>"));
}

}  // namespace

TEST_CASE("spatial report: self-contained, with the motion, the task and the figures", "[output]") {
    for (const char* name : {"s3-0004", "s4-0017"}) {
        testing::SpatialCase c = testing::planted_case(name);
        synth::choose_modules(c.task, hardware::load_default_catalog(), c.solution);
        output::ReportFigures figures;
        figures.front_seconds = 0.25;
        const std::string html = output::html_report(c.task, c.solution, figures);
        check_self_contained(html);
        const auto data = scene_data(html);
        const auto& chain = *c.solution.dh_robot;
        REQUIRE(data["motion"]["t"].size() == c.solution.samples.size());
        CHECK(data["motion"]["q"].size() == c.solution.samples.size() * chain.dof());
        CHECK(data["motion"]["t"].back().get<double>() ==
              Approx(c.solution.samples.back().t).margin(1e-6));
        REQUIRE(data["robot"]["dh"].size() == static_cast<std::size_t>(chain.dof()));
        for (int k = 0; k < chain.dof(); ++k) {
            CHECK(data["robot"]["dh"][k][0].get<double>() == Approx(chain.rows[k].a).margin(1e-6));
            CHECK(data["robot"]["dh"][k][1].get<double>() ==
                  Approx(chain.rows[k].alpha).margin(1e-9));
            CHECK(data["robot"]["dh"][k][2].get<double>() == Approx(chain.rows[k].d).margin(1e-6));
        }
        CHECK(data["task"]["prims"].size() == c.task.trajectory.size());
        CHECK(data["task"]["obstacles"].size() == c.task.obstacles.size());
        CHECK(data["task"]["regions"].size() == c.task.base_regions.size());
        CHECK(data["names"][0] == "trajectory[0]");
        // Every pose of the arm lies within the bounds the camera frames.
        const auto& lo = data["bounds"]["min"];
        const auto& hi = data["bounds"]["max"];
        for (const auto& x : c.solution.samples) {
            const auto ee = kinematics::end_effector(chain, x.q);
            for (int i = 0; i < 3; ++i) {
                CHECK(ee[i] >= lo[i].get<double>() - 1e-6);
                CHECK(ee[i] <= hi[i].get<double>() + 1e-6);
            }
        }
        for (const char* id : {"fig-dof", "fig-dh", "fig-base", "fig-length", "fig-clearance",
                               "fig-deviation", "fig-modules", "fig-samples", "stage-times"})
            CHECK(has(html, std::string("<tr id=\"") + id + "\">"));
        CHECK(has(html, "front stage 0.250 s"));
        CHECK(has(html, "in base_regions[0]"));
        // The timing charts of the plane, with the default limits dashed.
        for (const char* id : {"chart-q", "chart-qd", "chart-qdd"})
            CHECK(has(html, std::string("id=\"") + id + "\""));
        for (const char* id : {"play", "scrub", "clock", "speed", "view"})
            CHECK(has(html, std::string("id=\"") + id + "\""));
        CHECK_FALSE(has(html, "not certified"));
    }
}

TEST_CASE("spatial report of an infeasible task names the core and draws no arm", "[output]") {
    testing::SpatialCase c = testing::planted_case("s3-0001");
    synth::Solution s;
    s.task_name = c.task.name;
    s.status = synth::Status::Infeasible;
    s.explanation.message = "trajectory[0] <is> out of reach";
    s.explanation.core = {modsynth::task::TaskPart::trajectory(0),
                          modsynth::task::TaskPart::obstacle(0),
                          modsynth::task::TaskPart::base_regions()};
    const std::string html = output::html_report(c.task, s, {});
    check_self_contained(html);
    const auto data = scene_data(html);
    CHECK(data["robot"].is_null());
    CHECK(data["motion"].is_null());
    CHECK(data["task"]["prims"][0]["core"] == true);
    CHECK(data["task"]["regions"][0]["core"] == true);
    CHECK(has(html, "trajectory[0] &lt;is&gt; out of reach"));
    CHECK_FALSE(has(html, "id=\"play\""));
    CHECK_FALSE(has(html, "id=\"timing\""));
}

namespace {

/// An infeasible solution of s3-0001 with a made-up wall witness of two
/// runs of cells round its base region, behind obstacle 0.
synth::Solution walled_solution(const task::SpatialTask& task) {
    synth::Solution s;
    s.task_name = task.name;
    s.status = synth::Status::Infeasible;
    s.explanation.message = "obstacles 0 close a shell round base_regions[0]";
    s.explanation.core = {modsynth::task::TaskPart::trajectory(0),
                          modsynth::task::TaskPart::obstacle(0),
                          modsynth::task::TaskPart::base_regions()};
    prove::Enclosure w;
    w.point = geometry::Vec3(0.5, 0.25, 0.125);
    w.obstacles = {0};
    w.grid = {geometry::Vec3(-1.0, -1.0, -1.0), 0.25, {8, 8, 8}};
    w.base_inside = true;
    w.cells = {{3, 3, 2, 4}, {4, 3, 3, 3}};
    s.explanation.enclosure = prove::EnclosureWitness{{w}};
    return s;
}

}  // namespace

TEST_CASE("spatial report of a walled task draws the wall and the enclosed cells", "[output]") {
    testing::SpatialCase c = testing::planted_case("s3-0001");
    const synth::Solution s = walled_solution(c.task);
    const std::string html = output::html_report(c.task, s, {});
    check_self_contained(html);
    const auto data = scene_data(html);
    REQUIRE(data["enclosure"].size() == 1);
    const auto& w = data["enclosure"][0];
    CHECK(w["inside"] == "base_region");
    CHECK(w["obstacles"] == nlohmann::json::array({0}));
    // Run (j 3, k 3, i 2-4): x from -1 + 2 * 0.25 to -1 + 5 * 0.25.
    REQUIRE(w["runs"].size() == 2);
    const std::vector<double> run0 = w["runs"][0];
    CHECK(run0 == std::vector<double>{-0.5, -0.25, -0.25, 0.25, 0.0, 0.0});
    CHECK(data["task"]["obstacles"][0]["core"] == true);
    CHECK(has(html, "The proof's wall"));
}

TEST_CASE("the build sheet of an infeasible spatial task says why, and export writes it",
          "[output]") {
    testing::SpatialCase c = testing::planted_case("s3-0001");
    const synth::Solution s = walled_solution(c.task);
    const std::string sheet = output::build_sheet(c.task, s);
    CHECK(has(sheet, "No arm to build: the task is infeasible"));
    CHECK(has(sheet, "## Why\n\n" + text::markdown_text(s.explanation.message)));
    CHECK(has(sheet, "- `obstacles[0]`"));
    CHECK(has(sheet, "- Obstacles 0 close in base_regions[0]; the path, "));
    // Unknown: said so, without claiming a proof.
    synth::Solution u;
    u.status = synth::Status(synth::Status::Kind::Unknown);
    u.explanation.message = "time limit";
    CHECK(has(output::build_sheet(c.task, u), "none was proved impossible"));
    // export writes it (no line saying it was skipped); the URDF is not.
    const auto dir = testing::scratch_dir("spatial_walled_exports");
    output::ExportPaths paths;
    paths.build_sheet = (dir / "sheet.md").string();
    paths.urdf = (dir / "arm.urdf").string();
    const auto skipped = output::write_exports(c.task, s, paths, {});
    CHECK(fs::exists(dir / "sheet.md"));
    CHECK_FALSE(fs::exists(dir / "arm.urdf"));
    REQUIRE(skipped.size() == 1);
    CHECK(has(skipped[0], "--urdf"));
}

TEST_CASE("spatial report of an edited motion says it is not certified", "[output]") {
    testing::SpatialCase c = testing::planted_case("s4-0010");
    c.solution.samples[5].q[1] += 0.2;
    io::ParsedSolution parsed{c.solution, true};
    output::recertify(c.task, parsed);
    REQUIRE_FALSE(parsed.solution.certificate.ok);
    const std::string html = output::html_report(c.task, parsed.solution, {});
    CHECK(has(html, "<strong>not certified</strong>: samples["));
    CHECK(has(html, "Uncertified min. clearance"));
    const std::string sheet = output::build_sheet(c.task, parsed.solution);
    CHECK(has(sheet, "**Warning:** not certified"));
}

TEST_CASE("a spatial motion saved without rates is timed to a stop at its path's corners",
          "[output]") {
    // Where the tangent turns at a junction the tool cannot keep its speed
    // and stay on the path; where it does not, it need not stop.
    int corners = 0, smooth = 0;
    for (const char* name : {"s3-0001", "s3-0004", "s3-0017", "s4-0010"}) {
        const testing::SpatialCase c = testing::planted_case(name);
        const auto& samples = c.solution.samples;
        REQUIRE(!samples.front().qd.empty());
        const auto stops = control::path_corners(c.task, samples);
        for (std::size_t i = 0; i + 1 < samples.size(); ++i) {
            const control::Sample& a = samples[i];
            const control::Sample& b = samples[i + 1];
            if (a.phase != control::Phase::Trace || b.phase != control::Phase::Trace ||
                b.primitive != a.primitive + 1)
                continue;
            const int j = control::primitive_index(c.task, a);
            const auto& p = c.task.trajectory[j];
            const geometry::Vec3 before = geometry::tangent_at(p, geometry::length(p));
            const geometry::Vec3 after = geometry::tangent_at(c.task.trajectory[j + 1], 0.0);
            const double turn =
                std::acos(std::clamp(before.normalized().dot(after.normalized()), -1.0, 1.0));
            const bool listed = std::find(stops.begin(), stops.end(), i) != stops.end();
            CHECK(listed == (turn > control::kCornerAngle));
            if (turn > control::kCornerAngle) {
                ++corners;
                for (double v : a.qd) CHECK(v == Approx(0.0).margin(1e-9));
            } else {
                ++smooth;
            }
        }
    }
    CHECK(corners > 0);
    INFO("smooth junctions: " << smooth);
}

TEST_CASE("CSV and joint trajectory of spatial arms with 3 to 6 joints", "[output]") {
    for (int n = 3; n <= 6; ++n) {
        const synth::Solution s = testing::swinging_chain(n);
        const auto rows = lines_of(output::trajectory_csv(s));
        REQUIRE(rows.size() == s.samples.size() + 1);
        std::string header = "t";
        for (int k = 1; k <= n; ++k) header += ",q" + std::to_string(k);
        header += ",phase,primitive";
        for (int k = 1; k <= n; ++k) header += ",qd" + std::to_string(k);
        for (int k = 1; k <= n; ++k) header += ",qdd" + std::to_string(k);
        CHECK(rows[0] == header);
        for (std::size_t i = 1; i < rows.size(); ++i) CHECK(count(rows[i], ",") == 3 * n + 2);
        CHECK(rows[7].rfind(std::to_string(s.samples[6].t).substr(0, 4), 0) == 0);

        const std::string yaml = output::joint_trajectory_yaml(s);
        std::string names = "joint_names: [";
        for (int k = 0; k < n; ++k) names += (k ? ", joint_" : "joint_") + std::to_string(k + 1);
        CHECK(has(yaml, names + "]"));
        CHECK(count(yaml, "  - positions: ") == static_cast<int>(s.samples.size()));
        // Each list holds n numbers.
        const std::regex positions("  - positions: \\[([^\\]]*)\\]");
        for (auto it = std::sregex_iterator(yaml.begin(), yaml.end(), positions);
             it != std::sregex_iterator(); ++it)
            CHECK(count((*it)[1].str(), ",") == n - 1);
        CHECK(has(yaml, "sec: 2\n      nanosec: 0"));
    }
}

TEST_CASE("spatial URDF: joints from the DH rows, limits, modules and ros2_control", "[output]") {
    const auto catalog = hardware::load_default_catalog();
    for (int n = 3; n <= 6; ++n) {
        task::SpatialTask task;
        task.name = "arm <" + std::to_string(n) + ">";
        task.robot.dof = {n};
        const synth::Solution s = testing::swinging_chain(n);
        const std::string urdf = output::robot_urdf(task, s, catalog);
        CHECK(has(urdf, "<robot name=\"arm__" + std::to_string(n) + "_\">"));
        CHECK(count(urdf, "type=\"revolute\"") == n);
        CHECK(count(urdf, "<axis xyz=\"0 0 1\"/>") == n);
        CHECK(count(urdf, "<inertial>") == n + 1);
        CHECK(count(urdf, "<command_interface name=\"position\"/>") == n);
        CHECK(has(urdf, "<link name=\"ee\"/>"));
        // The tool frame's z is the tool's axis (formats.md): the last
        // segment, x_n here (a_n > 0), so a quarter turn about y.
        REQUIRE(s.dh_robot->rows.back().a > 0.0);
        CHECK(has(urdf,
                  "<child link=\"tool\"/>\n    <origin xyz=\"0.000000 0.000000 0.000000\" "
                  "rpy=\"0.000000 1.570796 0.000000\"/>"));
        // Joint 2 sits at (a_1, 0, d_1), turned by alpha_1 about x.
        const auto& r = s.dh_robot->rows[0];
        CHECK(has(urdf, "<origin xyz=\"" + text::format("%.6f 0.000000 %.6f", r.a, r.d) +
                            "\" rpy=\"" + text::format("%.6f", r.alpha) +
                            " 0.000000 0.000000\"/>"));
        // Limits: the motion's range plus the margin; the strongest module.
        double lo = 1e9, hi = -1e9;
        for (const auto& x : s.samples) lo = std::min(lo, x.q[0]), hi = std::max(hi, x.q[0]);
        CHECK(has(urdf, "<limit lower=\"" + text::format("%.6f", lo - 0.05) + "\" upper=\"" +
                            text::format("%.6f", hi + 0.05) + "\" effort=\"38.000000\""));
    }
}

TEST_CASE("spatial build sheet: tubes, brackets, modules, base and start pose", "[output]") {
    testing::SpatialCase c = testing::planted_case("s4-0010");
    synth::choose_modules(c.task, hardware::load_default_catalog(), c.solution);
    REQUIRE(c.solution.modules);
    const std::string sheet = output::build_sheet(c.task, c.solution);
    const auto stack = hardware::dh_stack(c.task.robot, *c.solution.dh_robot);
    CHECK(has(sheet, "# Build sheet: s4\\-0010"));
    CHECK(has(sheet, "A spatial arm with 4 joints"));
    CHECK(has(sheet, "| right-angle bracket | 1 |"));
    CHECK(has(sheet, "| 2 | link 1's tube | 90.0 | right-angle bracket"));
    CHECK(has(sheet, "| 3 | link 2's tube | 0.0 | tube adapter"));
    CHECK(count(sheet, "\\| common normal \\(a\\) \\||\\| joint axis \\(d\\) \\|") ==
          static_cast<int>(stack.tubes.size()));
    for (const auto& t : stack.tubes)
        CHECK(has(sheet, "**" + text::format("%.1f", 1000.0 * t.cut_length) + "**"));
    CHECK(has(sheet, "## Modules"));
    CHECK(has(sheet, "## Base"));
    CHECK(has(sheet, text::format("%.4f", c.solution.dh_robot->base.z())));
    CHECK(has(sheet, "## Start pose"));
    CHECK_FALSE(has(sheet, "**Warning:**"));
    // An arm that no allowed module carries says so on top of the modules.
    c.task.robot.payload = 4.0;
    c.task.robot.modules = {"X5-1"};
    synth::choose_modules(c.task, hardware::load_default_catalog(), c.solution);
    const std::string heavy = output::build_sheet(c.task, c.solution);
    CHECK(has(heavy, "**Warning:** joint "));
    CHECK(has(heavy, "**(overloaded)**"));
}

TEST_CASE("write_exports writes every output of a spatial solution", "[output]") {
    testing::SpatialCase c = testing::planted_case("s3-0017");
    const auto dir = testing::scratch_dir("spatial_exports");
    output::ExportPaths paths;
    paths.report = (dir / "r.html").string();
    paths.urdf = (dir / "r.urdf").string();
    paths.csv = (dir / "r.csv").string();
    paths.build_sheet = (dir / "r.md").string();
    paths.joint_trajectory = (dir / "r.yaml").string();
    CHECK(output::write_exports(c.task, c.solution, paths, {}).empty());
    CHECK(has(read(paths.report), "id=\"scene-data\""));
    CHECK(has(read(paths.urdf), "<robot name=\"s3-0017\">"));
    CHECK(lines_of(read(paths.csv)).size() == c.solution.samples.size() + 1);
    CHECK(has(read(paths.build_sheet), "A spatial arm with 3 joints"));
    CHECK(has(read(paths.joint_trajectory), "joint_names: [joint_1, joint_2, joint_3]"));
    // Without a robot, only the report and the build sheet saying why.
    synth::Solution none;
    none.status = synth::Status::Unknown;
    none.explanation.message = "gave up";
    fs::remove(paths.urdf);
    const auto skipped = output::write_exports(c.task, none, paths, {});
    CHECK(skipped.size() == 3);
    CHECK(has(read(paths.build_sheet), "No arm to build"));
    CHECK(has(skipped[0], "--urdf"));
    CHECK(has(skipped[0], "so there is no robot"));
    CHECK_FALSE(fs::exists(paths.urdf));
    CHECK(has(read(paths.report), "Why no robot was found"));
}
