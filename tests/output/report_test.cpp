#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <regex>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include <modsynth/io/task_io.h>
#include <modsynth/output/report.h>
#include <modsynth/synth/synthesizer.h>

#include "../support/fixtures.h"

#include "output_fixtures.h"

namespace testing = modsynth::testing;
using modsynth::output::html_report;
using modsynth::output::ReportFigures;

namespace {

int count(const std::string& text, const std::string& pattern) {
    const std::regex re(pattern);
    return static_cast<int>(
        std::distance(std::sregex_iterator(text.begin(), text.end(), re), std::sregex_iterator()));
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

/// The contents of the table cell of figure `id`.
std::string figure(const std::string& html, const std::string& id) {
    std::smatch m;
    const std::regex re("<tr id=\"" + id + "\"><th>[^<]*</th><td>(.*?)</td></tr>");
    return std::regex_search(html, m, re) ? m[1].str() : "(missing " + id + ")";
}

nlohmann::json motion_data(const std::string& html) {
    std::smatch m;
    const std::regex re("<script type=\"application/json\" id=\"motion-data\">(.*?)</script>");
    REQUIRE(std::regex_search(html, m, re));
    return nlohmann::json::parse(m[1].str());
}

void check_self_contained(const std::string& html) {
    CHECK(html.rfind("<!DOCTYPE html>", 0) == 0);
    CHECK_FALSE(has(html, "http://"));
    CHECK_FALSE(has(html, "https://"));
    CHECK_FALSE(has(html, " src="));
    CHECK_FALSE(has(html, "<link"));
    CHECK(count(html, "<g[ >]") == count(html, "</g>"));
    CHECK(count(html, "<svg[ >]") == 1);
    CHECK(has(html, "</svg>"));
    CHECK(has(html, "</html>"));
}

void check_task_layers(const std::string& html, const modsynth::task::Task& task) {
    for (const char* id : {"base-regions", "obstacles", "trajectory", "scale-bar"}) {
        CHECK(has(html, std::string("<g id=\"") + id + "\">"));
    }
    CHECK(count(html, "class=\"primitive( core)?\"") == static_cast<int>(task.trajectory.size()));
    CHECK(count(html, "class=\"obstacle( core)?\"") == static_cast<int>(task.obstacles.size()));
    CHECK(count(html, "class=\"base-region( core)?\"") ==
          static_cast<int>(task.base_regions.size()));
    for (std::size_t j = 0; j < task.trajectory.size(); ++j) {
        CHECK(has(html, "data-part=\"trajectory[" + std::to_string(j) + "]\""));
    }
}

void check_robot_layers(const std::string& html, const modsynth::synth::Solution& s,
                        int primitives) {
    for (const char* id : {"reachable", "swept", "poses", "robot"}) {
        CHECK(has(html, std::string("<g id=\"") + id + "\">"));
    }
    CHECK(count(html, "class=\"swept\"") == primitives);
    CHECK(count(html, "class=\"pose\"") == primitives);
    CHECK(count(html, "class=\"link\"") == s.robot.dof());
    CHECK(count(html, "class=\"joint\"") == s.robot.dof());
    CHECK(count(html, "class=\"ee\"") == 1);
    CHECK(has(html, "<polyline id=\"trail\""));
}

void check_animation(const std::string& html, const modsynth::synth::Solution& s) {
    CHECK(has(html, "<button id=\"play\""));
    CHECK(has(html, "<input id=\"scrub\" type=\"range\""));
    CHECK(has(html, "<select id=\"speed\""));
    CHECK(has(html, "requestAnimationFrame"));
    const auto data = motion_data(html);
    REQUIRE(data["t"].size() == s.samples.size());
    CHECK(data["q"].size() == s.samples.size() * s.robot.link_lengths.size());
    CHECK(data["pr"].size() == s.samples.size());
    CHECK(data["t"].back().get<double>() == Approx(s.samples.back().t).margin(1e-6));
    CHECK(data["q"][1].get<double>() == Approx(s.samples[0].q[1]).margin(1e-6));
    CHECK(data["L"].size() == s.robot.link_lengths.size());
}

}  // namespace

TEST_CASE("the report of a 2-joint solution shows task, robot, motion and figures", "[output]") {
    const auto task = testing::two_joint_task();
    const auto s = testing::two_joint_solution(task);
    const std::string html = html_report(task, s, ReportFigures{});
    check_self_contained(html);
    check_task_layers(html, task);
    check_robot_layers(html, s, 2);
    check_animation(html, s);
    CHECK(count(html, "class=\"reach\"") == 1);  // one reachable space for the whole motion
    CHECK(count(html, " core\"") == 0);
    CHECK(figure(html, "fig-status") == "solved");
    CHECK(figure(html, "fig-dof") == "2");
    CHECK(figure(html, "fig-links") == "350.0 mm, 300.0 mm (total 650.0 mm)");
    CHECK(figure(html, "fig-base") == "(0.0000, 0.0000) m, in base_regions[0]");
    CHECK(has(figure(html, "fig-clearance"), "12.30 mm"));
    CHECK(has(figure(html, "fig-deviation"), "0.025 mm"));
    CHECK(has(figure(html, "fig-samples"), std::to_string(s.samples.size()) + " samples"));
    CHECK(has(figure(html, "stage-times"), "n/a"));
    CHECK(has(html, "id=\"reach-caption\""));
}

TEST_CASE("the report shows stage timings when synthesis gives them", "[output]") {
    const auto task = testing::two_joint_task();
    const auto s = testing::two_joint_solution(task);
    ReportFigures figures;
    figures.front_seconds = 0.125;
    figures.refine_seconds = 1.5;
    figures.verify_seconds = 0.25;
    const std::string html = html_report(task, s, figures);
    CHECK(figure(html, "stage-times") ==
          "front stage 0.125 s, refinement 1.500 s, verification 0.250 s");
}

TEST_CASE("the report of a 3-joint solution shades per primitive and shows transitions",
          "[output]") {
    const auto task = testing::three_joint_task();
    const auto s = testing::three_joint_solution(task);
    const std::string html = html_report(task, s, ReportFigures{});
    check_self_contained(html);
    check_task_layers(html, task);
    check_robot_layers(html, s, 2);
    check_animation(html, s);
    CHECK(count(html, "class=\"reach\" data-primitive=\"[0-9]+\"") == 2);
    CHECK(count(html, "class=\"swept-transition\"") == 1);
    CHECK(figure(html, "fig-dof") == "3");
    CHECK(has(html, "leading links held"));  // the shading says what it approximates
}

TEST_CASE("the report of an infeasible task highlights the core and explains", "[output]") {
    const auto task = testing::two_joint_task();
    const auto s = testing::infeasible_solution(task);
    const std::string html = html_report(task, s, ReportFigures{});
    check_self_contained(html);
    check_task_layers(html, task);
    CHECK(has(html, "class=\"primitive core\" data-part=\"trajectory[1]\""));
    CHECK(has(html, "class=\"primitive\" data-part=\"trajectory[0]\""));
    CHECK(has(html, "class=\"obstacle core\" data-part=\"obstacles[0]\""));
    CHECK(has(html, "class=\"obstacle\" data-part=\"obstacles[1]\""));
    CHECK(has(html, "class=\"base-region core\" data-part=\"base_regions[0]\""));
    CHECK(has(html, "class=\"reach-limit core\" data-part=\"robot.max_link_length\""));
    CHECK(has(html, "No robot &lt;can&gt; do this &amp; that"));  // escaped
    CHECK(count(html, "<li class=\"core-part\"") == 4);
    CHECK(figure(html, "fig-status") == "infeasible");
    CHECK_FALSE(has(html, "id=\"play\""));
    CHECK_FALSE(has(html, "id=\"motion-data\""));
    CHECK_FALSE(has(html, "<g id=\"robot\">"));
}

TEST_CASE("the report shows a hostile task name as text, never as markup", "[output][escape]") {
    auto task = testing::two_joint_task();
    task.name = "<script>alert('x')</script> `b` | c\n]]> \"qq7\" &amp;\x01";
    const auto s = testing::two_joint_solution(task);
    const std::string html = html_report(task, s, ReportFigures{});
    CHECK_FALSE(has(html, "<script>alert"));
    CHECK_FALSE(has(html, "\"qq7\""));
    CHECK_FALSE(has(html, "\x01"));
    const std::string shown =
        "&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; `b` | c\n]]&gt; &quot;qq7&quot; "
        "&amp;amp;\xEF\xBF\xBD";
    CHECK(has(html, "<title>modsynth: " + shown + "</title>"));
    CHECK(has(html, "<h1>" + shown + " <span"));
}

namespace {

// Numbers of every "x,y" pair after each M or A command's radii in a lens
// path: its two corners, each on both discs' circles.
std::vector<std::pair<double, double>> lens_corners(const std::string& d) {
    std::vector<std::pair<double, double>> out;
    const std::regex corner("(?:M|A[0-9.]+,[0-9.]+ 0 [01],[01] )(-?[0-9.]+),(-?[0-9.]+)");
    for (auto it = std::sregex_iterator(d.begin(), d.end(), corner); it != std::sregex_iterator();
         ++it)
        out.push_back({std::stod((*it)[1]), std::stod((*it)[2])});
    return out;
}

modsynth::task::Task infeasible_task(const std::string& name) {
    return modsynth::io::load_task(testing::source_path("tasks/infeasible/" + name + ".task.json"));
}

}  // namespace

TEST_CASE("the report of a walled-in task draws the wall and where its discs overlap",
          "[output][walls]") {
    const auto task = infeasible_task("ring-around-path");
    const auto s = modsynth::synth::synthesize(task, {});
    REQUIRE(s.status == modsynth::synth::Status::Infeasible);
    REQUIRE(s.explanation.separation);
    const auto& wall = s.explanation.separation->walls.at(0);
    const std::string html = html_report(task, s, ReportFigures{});
    check_self_contained(html);
    check_task_layers(html, task);
    CHECK(count(html, "<g id=\"proof\">") == 1);
    CHECK(count(html, "class=\"wall\"") == 1);
    const int n = static_cast<int>(wall.cycle.size());
    CHECK(count(html, "class=\"wall-disc\"") == n);
    CHECK(count(html, "class=\"wall-overlap\"") == n);
    CHECK(count(html, "class=\"wall-cycle\"") == 1);
    CHECK(count(html, "class=\"proof-point\"") == 1);
    CHECK(has(html, "id=\"proof-caption\""));
    CHECK(has(html, "data-pair=\"" + std::to_string(wall.cycle[0]) + "-" +
                        std::to_string(wall.cycle[1]) + "\""));
    // Each lens's corners lie on both no-go circles (in pixels: the disc
    // elements say where the circles are).
    const std::regex disc(
        "class=\"wall-disc\" data-obstacle=\"([0-9]+)\" cx=\"([0-9.]+)\" cy=\"([0-9.]+)\" "
        "r=\"([0-9.]+)\"");
    std::map<int, std::array<double, 3>> circles;
    for (auto it = std::sregex_iterator(html.begin(), html.end(), disc);
         it != std::sregex_iterator(); ++it)
        circles[std::stoi((*it)[1])] = {std::stod((*it)[2]), std::stod((*it)[3]),
                                        std::stod((*it)[4])};
    REQUIRE(static_cast<int>(circles.size()) == n);
    const std::regex lens("data-pair=\"([0-9]+)-([0-9]+)\" d=\"([^\"]+)\"");
    int lenses = 0;
    for (auto it = std::sregex_iterator(html.begin(), html.end(), lens);
         it != std::sregex_iterator(); ++it, ++lenses) {
        const auto corners = lens_corners((*it)[3]);
        REQUIRE(corners.size() == 3);  // M p, A .. q, A .. p
        for (int k : {std::stoi((*it)[1]), std::stoi((*it)[2])}) {
            const auto& c = circles.at(k);
            for (const auto& [x, y] : corners)
                CHECK(std::hypot(x - c[0], y - c[1]) == Approx(c[2]).margin(0.02));
        }
    }
    CHECK(lenses == n);
}

TEST_CASE("the report of a task beyond reach around a wall draws the detour and its length",
          "[output][walls]") {
    const auto task = infeasible_task("long-wall");
    const auto s = modsynth::synth::synthesize(task, {});
    REQUIRE(s.status == modsynth::synth::Status::Infeasible);
    REQUIRE(s.explanation.geodesic);
    const auto& d = s.explanation.geodesic->detours.at(0);
    const std::string html = html_report(task, s, ReportFigures{});
    check_self_contained(html);
    CHECK(count(html, "class=\"detour\"") == 1);
    CHECK(count(html, "class=\"wall\"") == 0);
    char label[96];
    std::snprintf(label, sizeof label, "at least %.2f m; reach %.2f m", d.lower_bound,
                  s.explanation.geodesic->reach);
    CHECK(count(html, label) == 1);  // in the route's title
    char first[64];                  // and on the plot, in two lines
    std::snprintf(first, sizeof first, "at least %.2f m</tspan>", d.lower_bound);
    CHECK(has(html, "class=\"detour-length\""));
    CHECK(has(html, first));
    // One drawing command per route step: a line, or an arc around an obstacle.
    std::smatch m;
    REQUIRE(std::regex_search(html, m, std::regex("class=\"detour\"[^>]* d=\"([^\"]+)\"")));
    const std::string path = m[1];
    CHECK(count(path, "[LA]") == static_cast<int>(d.route.size()) - 1);
    int arcs = 0;
    for (const auto& step : d.route) arcs += step.around >= 0;
    CHECK(count(path, "A") == arcs);
    CHECK(arcs > 0);
}

TEST_CASE("a solved or front-stage-infeasible report has no proof layer", "[output][walls]") {
    const auto task = testing::two_joint_task();
    CHECK_FALSE(
        has(html_report(task, testing::two_joint_solution(task), ReportFigures{}), "id=\"proof\""));
    CHECK_FALSE(has(html_report(task, testing::infeasible_solution(task), ReportFigures{}),
                    "id=\"proof\""));
}

namespace {

/// Hue (degrees), saturation and value of "#rrggbb".
std::array<double, 3> hsv(const std::string& hex) {
    unsigned r = 0, g = 0, b = 0;
    std::sscanf(hex.c_str(), "#%02x%02x%02x", &r, &g, &b);
    const double R = r / 255.0, G = g / 255.0, B = b / 255.0;
    const double hi = std::max({R, G, B}), lo = std::min({R, G, B}), d = hi - lo;
    double h = 0.0;
    if (d > 0.0) {
        if (hi == R)
            h = 60.0 * std::fmod((G - B) / d + 6.0, 6.0);
        else if (hi == G)
            h = 60.0 * ((B - R) / d + 2.0);
        else
            h = 60.0 * ((R - G) / d + 4.0);
    }
    return {h, hi > 0.0 ? d / hi : 0.0, hi};
}

}  // namespace

TEST_CASE("the path's colours mean nothing else: no red, green or grey among them", "[output]") {
    // Ten primitives, the whole palette, in a report with a core (red) shown.
    auto task = testing::two_joint_task();
    while (task.trajectory.size() < 10) {
        const modsynth::geometry::Vec2 end = task.trajectory.back().end;
        task.trajectory.push_back(
            modsynth::geometry::make_line(end, end + modsynth::geometry::Vec2(0.0, 0.01)));
    }
    const std::string html = html_report(task, testing::infeasible_solution(task), ReportFigures{});
    const std::regex swatch("class=\"swatch\" style=\"background:(#[0-9a-f]{6})\"");
    std::set<std::string> colours;
    for (auto it = std::sregex_iterator(html.begin(), html.end(), swatch);
         it != std::sregex_iterator(); ++it)
        colours.insert((*it)[1]);
    CHECK(colours.size() == 10);
    for (const std::string& c : colours) {
        const auto [h, s, v] = hsv(c);
        INFO(c << ": hue " << h << ", saturation " << s << ", value " << v);
        CHECK(s > 0.3);  // not grey (the arm, base regions)
        // Not red (obstacles, a core): a dark, dull red is brown, no red.
        CHECK_FALSE(((h < 20.0 || h > 340.0) && s > 0.5 && v > 0.6));
        CHECK_FALSE((h > 95.0 && h < 160.0));  // not green (a wall's cells)
    }
}

TEST_CASE("the timing charts' curves are not styled as the robot's joints", "[output]") {
    const auto task = testing::two_joint_task();
    // A timed motion (rates and accelerations), which the charts draw.
    auto solution = testing::two_joint_solution(task);
    for (std::size_t i = 0; i < solution.samples.size(); ++i) {
        auto& x = solution.samples[i];
        x.qd.assign(x.q.size(), 0.1 * std::sin(0.01 * static_cast<double>(i)));
        x.qdd.assign(x.q.size(), 0.1 * std::cos(0.01 * static_cast<double>(i)));
    }
    const std::string html = html_report(task, solution, ReportFigures{});
    // Four charts of the two joints, and the tool's speed.
    CHECK(count(html, "<polyline class=\"joint-curve\"") == 9);
    CHECK(count(html, "<polyline class=\"joint\"") == 0);
    // The rules for the arm's circles apply inside the robot alone.
    CHECK_FALSE(has(html, "\n.joint {"));
    CHECK(has(html, "#robot .joint {"));
    CHECK(has(html, ".chart polyline { fill: none; }"));
    CHECK(has(html, "<li data-joint=\"1\"><span class=\"swatch\""));
}
