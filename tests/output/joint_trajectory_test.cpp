#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <modsynth/control/joint_limits.h>
#include <modsynth/control/retime.h>
#include <modsynth/output/csv.h>
#include <modsynth/output/exports.h>
#include <modsynth/output/joint_trajectory.h>
#include <modsynth/output/report.h>
#include <modsynth/output/urdf.h>

#include "output_fixtures.h"

namespace testing = modsynth::testing;
using modsynth::synth::Solution;
namespace control = modsynth::control;
namespace output = modsynth::output;

namespace {

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream in(text);
    std::string line;
    while (std::getline(in, line)) out.push_back(line);
    return out;
}

std::vector<std::string> split(const std::string& text, char sep) {
    std::vector<std::string> out;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, sep)) out.push_back(item);
    return out;
}

/// The numbers of a flow list "[a, b, c]".
std::vector<double> numbers(const std::string& list) {
    std::vector<double> out;
    const auto open = list.find('['), close = list.find(']');
    for (const auto& x : split(list.substr(open + 1, close - open - 1), ','))
        if (!x.empty()) out.push_back(std::stod(x));
    return out;
}

Solution timed(Solution s, const control::JointLimits& limits) {
    s.samples = control::retime(std::move(s.samples), limits);
    return s;
}

}  // namespace

TEST_CASE("the CSV of a timed motion has velocity and acceleration columns", "[output][timing]") {
    const auto task = testing::three_joint_task();
    const Solution s = timed(testing::three_joint_solution(task), control::default_joint_limits(3));
    const auto rows = lines_of(output::trajectory_csv(s));
    REQUIRE(rows.size() == s.samples.size() + 1);
    CHECK(rows[0] == "t,q1,q2,q3,phase,primitive,qd1,qd2,qd3,qdd1,qdd2,qdd3");
    double last = -1.0;
    for (std::size_t i = 0; i < s.samples.size(); ++i) {
        const auto cells = split(rows[i + 1], ',');
        REQUIRE(cells.size() == 12);
        const auto& x = s.samples[i];
        CHECK(std::stod(cells[0]) == Approx(x.t).margin(1e-6));
        CHECK(std::stod(cells[0]) >= last);
        last = std::stod(cells[0]);
        for (int k = 0; k < 3; ++k) {
            CHECK(std::stod(cells[6 + k]) == Approx(x.qd[k]).margin(1e-9));
            CHECK(std::stod(cells[9 + k]) == Approx(x.qdd[k]).margin(1e-9));
        }
    }
}

TEST_CASE("the joint trajectory is a ROS 2 JointTrajectory of the timed motion",
          "[output][timing]") {
    const auto task = testing::two_joint_task();
    const Solution s = timed(testing::two_joint_solution(task), control::default_joint_limits(2));
    const auto lines = lines_of(output::joint_trajectory_yaml(s));
    // The joint names are the URDF's.
    std::vector<std::string> urdf_joints;
    const std::string urdf = output::robot_urdf(task, s);
    const std::regex joint("<joint name=\"([a-z_0-9]+)\" type=\"revolute\">");
    for (std::sregex_iterator it(urdf.begin(), urdf.end(), joint), end; it != end; ++it)
        urdf_joints.push_back((*it)[1]);
    REQUIRE(urdf_joints.size() == 2);
    std::string names;
    for (const auto& l : lines)
        if (l.rfind("joint_names: ", 0) == 0) names = l;
    CHECK(names == "joint_names: [" + urdf_joints[0] + ", " + urdf_joints[1] + "]");
    CHECK(std::find(lines.begin(), lines.end(), "header:") != lines.end());
    CHECK(std::find(lines.begin(), lines.end(), "points:") != lines.end());

    std::size_t point = 0;
    long long previous = -1;
    long long sec = 0;
    for (const auto& l : lines) {
        if (l.rfind("  - positions: ", 0) == 0) {
            REQUIRE(point < s.samples.size());
            const auto q = numbers(l);
            REQUIRE(q.size() == 2);
            CHECK(q[0] == Approx(s.samples[point].q[0]).margin(1e-9));
            ++point;
        } else if (l.rfind("    velocities: ", 0) == 0) {
            const auto v = numbers(l);
            REQUIRE(v.size() == 2);
            CHECK(v[1] == Approx(s.samples[point - 1].qd[1]).margin(1e-9));
        } else if (l.rfind("    accelerations: ", 0) == 0) {
            CHECK(numbers(l).size() == 2);
        } else if (l.rfind("      sec: ", 0) == 0) {
            sec = std::stoll(l.substr(11));
        } else if (l.rfind("      nanosec: ", 0) == 0) {
            const long long ns = std::stoll(l.substr(15));
            CHECK(ns >= 0);
            CHECK(ns < 1'000'000'000LL);
            const long long stamp = sec * 1'000'000'000LL + ns;
            CHECK(stamp > previous);  // strictly increasing
            CHECK(static_cast<double>(stamp) == Approx(s.samples[point - 1].t * 1e9).margin(1.0));
            previous = stamp;
        }
    }
    CHECK(point == s.samples.size());
}

TEST_CASE("an untimed motion has no joint trajectory", "[output][timing]") {
    const Solution s = testing::two_joint_solution(testing::two_joint_task());
    CHECK_THROWS_WITH(output::joint_trajectory_yaml(s), Catch::Contains("not timed"));
}

TEST_CASE("the joint trajectory is written with the other exports", "[output][timing]") {
    const auto task = testing::two_joint_task();
    const Solution s = timed(testing::two_joint_solution(task), control::default_joint_limits(2));
    const auto dir = testing::scratch_dir("joint-trajectory");
    output::ExportPaths paths;
    paths.joint_trajectory = (dir / "t.yaml").string();
    CHECK(paths.any());
    CHECK(output::write_exports(task, s, paths, {}).empty());
    std::ifstream in(paths.joint_trajectory);
    std::stringstream text;
    text << in.rdbuf();
    CHECK(text.str() == output::joint_trajectory_yaml(s));

    Solution unsolved;
    unsolved.status = modsynth::synth::Status::Infeasible;
    const auto skipped = output::write_exports(task, unsolved, paths, {});
    REQUIRE(skipped.size() == 1);
    CHECK_THAT(skipped[0], Catch::StartsWith("--joint-trajectory"));
}

TEST_CASE("the report charts angles, velocities and accelerations with the limits",
          "[output][timing]") {
    auto task = testing::two_joint_task();
    task.robot.joint_limits = modsynth::task::JointLimitsSpec{{2.0, 1.5}, {6.0}};
    const auto limits = control::joint_limits_for(task, 2);
    const Solution s = timed(testing::two_joint_solution(task), limits);
    const std::string html = output::html_report(task, s, {});
    for (const char* id : {"chart-q", "chart-qd", "chart-qdd"})
        CHECK(html.find(std::string("id=\"") + id + "\"") != std::string::npos);
    CHECK(html.find("Joint limits of the task: velocity 2, 1.5 rad/s") != std::string::npos);
    // Two dashed lines (+ and -) per joint in the velocity and acceleration charts.
    std::size_t dashed = 0;
    for (auto at = html.find("class=\"limit\""); at != std::string::npos;
         at = html.find("class=\"limit\"", at + 1))
        ++dashed;
    CHECK(dashed == 8);
    CHECK(html.find(" Motion time ") == std::string::npos);  // starts the note
    CHECK(html.find(">Motion time ") != std::string::npos);
    CHECK(html.find("with 0 stops inside") != std::string::npos);
    // The jerks and the tool's speed are charted too; without jerk limits
    // there is nothing to dash in the jerk chart.
    CHECK(html.find("id=\"chart-jerk\"") != std::string::npos);
    CHECK(html.find("id=\"chart-tool-speed\"") != std::string::npos);

    // With jerk limits, dashed in the jerk chart as well.
    task.robot.joint_limits->jerk = {30.0};
    const auto jerky = control::joint_limits_for(task, 2);
    const std::string with_jerk =
        output::html_report(task, timed(testing::two_joint_solution(task), jerky), {});
    CHECK(with_jerk.find(", jerk 30, 30 rad/s&sup3;") != std::string::npos);
    std::size_t jerk_dashed = 0;
    for (auto at = with_jerk.find("class=\"limit\""); at != std::string::npos;
         at = with_jerk.find("class=\"limit\"", at + 1))
        ++jerk_dashed;
    CHECK(jerk_dashed == 12);

    // An untimed motion: no charts.
    const Solution bare = testing::two_joint_solution(task);
    CHECK(output::html_report(task, bare, {}).find("id=\"timing\"") == std::string::npos);
}
