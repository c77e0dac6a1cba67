#include <catch2/catch.hpp>

#include <cstdio>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include <modsynth/io/task_io.h>
#include <modsynth/output/build_sheet.h>
#include <modsynth/output/hardware.h>

#include "output_fixtures.h"

namespace testing = modsynth::testing;
using modsynth::output::tube_cuts;
using modsynth::task::InputError;
using nlohmann::json;

namespace {

std::string mm(double metres) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", 1000.0 * metres);
    return buf;
}

json minimal_task() {
    return {{"format", "modsynth-task/1"},
            {"trajectory", {{{"type", "line"}, {"start", {0.4, 0.0}}, {"end", {0.4, 0.2}}}}}};
}

}  // namespace

TEST_CASE("hardware sizes default to a HEBI X8 and 31.75 mm tubes", "[output]") {
    const auto t = modsynth::io::parse_task(minimal_task());
    CHECK(t.robot.module_length == 0.110);
    CHECK(t.robot.module_width == 0.073);
    CHECK(t.robot.module_height == 0.045);
    CHECK(t.robot.link_diameter == 0.03175);
    CHECK(t.robot.adapter_length > 0.0);
    CHECK(t.robot.ee_rod_diameter == 0.0095);
}

TEST_CASE("hardware sizes are optional robot keys, validated and round-tripped", "[output]") {
    json doc = minimal_task();
    doc["robot"] = {{"module_length", 0.2},
                    {"module_width", 0.08},
                    {"module_height", 0.05},
                    {"adapter_length", 0.01},
                    {"ee_rod_diameter", 0.012}};
    const auto t = modsynth::io::parse_task(doc);
    CHECK(t.robot.module_length == 0.2);
    CHECK(t.robot.module_width == 0.08);
    CHECK(t.robot.module_height == 0.05);
    CHECK(t.robot.adapter_length == 0.01);
    CHECK(t.robot.ee_rod_diameter == 0.012);
    const auto back = modsynth::io::parse_task(modsynth::io::to_json(t));
    CHECK(back.robot.module_length == 0.2);
    CHECK(back.robot.adapter_length == 0.01);
    CHECK(back.robot.ee_rod_diameter == 0.012);

    for (const char* key :
         {"module_length", "module_width", "module_height", "adapter_length", "ee_rod_diameter"}) {
        for (const json& bad : {json(0.0), json(-0.1), json("big"), json(nullptr)}) {
            json d = minimal_task();
            d["robot"] = {{key, bad}};
            try {
                modsynth::io::parse_task(d);
                FAIL(std::string(key) + " = " + bad.dump() + " accepted");
            } catch (const InputError& e) {
                CHECK(e.part() == std::string("robot.") + key);
            }
        }
    }
}

TEST_CASE("tube cut lengths are link lengths minus the module and adapter allowances", "[output]") {
    modsynth::task::RobotSpec spec;  // X8: 110 x 73 x 45 mm
    spec.adapter_length = 0.020;
    modsynth::kinematics::Robot robot;
    robot.link_lengths = {0.547, 0.420, 0.300};
    robot.link_diameter = 0.03175;
    const auto cuts = tube_cuts(spec, robot);
    REQUIRE(cuts.size() == 3);
    // Output end: half the 73 mm width plus the adapter.
    for (const auto& c : cuts) CHECK(c.proximal_allowance == Approx(0.0365 + 0.020));
    // Far end of an inner tube: the 110 mm body behind the next axis (110 - 36.5) plus the adapter.
    CHECK(cuts[0].distal_allowance == Approx(0.0735 + 0.020));
    CHECK(cuts[1].distal_allowance == Approx(0.0735 + 0.020));
    CHECK(cuts[0].cut_length == Approx(0.547 - 0.0565 - 0.0935));  // 397.0 mm
    CHECK(cuts[1].cut_length == Approx(0.420 - 0.0565 - 0.0935));  // 270.0 mm
    // The last tube runs half its diameter past the rod.
    CHECK(cuts[2].last);
    CHECK(cuts[2].distal_allowance == Approx(-0.03175 / 2));
    CHECK(cuts[2].cut_length == Approx(0.300 - 0.0565 + 0.015875));  // 259.4 mm
}

TEST_CASE("the build sheet lists parts, cuts, stack, base and start pose", "[output]") {
    const auto task = testing::two_joint_task();
    const auto s = testing::two_joint_solution(task);
    const std::string sheet = modsynth::output::build_sheet(task, s);
    CHECK(sheet.find("# Build sheet: line") == 0);
    CHECK(sheet.find("| actuator module (default: HEBI X8) | 2 | 110.0 x 73.0 x 45.0 mm |") !=
          std::string::npos);
    CHECK(sheet.find("| tube | 2 | 31.8 mm diameter") != std::string::npos);
    CHECK(sheet.find("| tube adapter | 3 |") != std::string::npos);
    const auto cuts = tube_cuts(task.robot, s.robot);
    for (std::size_t k = 0; k < cuts.size(); ++k) {
        const std::string row = "| " + std::to_string(k + 1) + " | " + mm(cuts[k].link_length) +
                                " | " + mm(cuts[k].proximal_allowance) + " | " +
                                mm(cuts[k].distal_allowance) + " | **" + mm(cuts[k].cut_length) +
                                "** |";
        CHECK(sheet.find(row) != std::string::npos);
    }
    CHECK(sheet.find("x = 0.0000 m, y = 0.0000 m") != std::string::npos);
    char q1[64];
    std::snprintf(q1, sizeof q1, "| 1 | %.4f |", s.samples.front().q[0]);
    CHECK(sheet.find(q1) != std::string::npos);
    CHECK(sheet.find("(0.4000, 0.0500) m") != std::string::npos);  // the path's start
    CHECK(sheet.find("Warning") == std::string::npos);
}

TEST_CASE("the build sheet warns when a link is too short for the modules", "[output]") {
    auto task = testing::three_joint_task();
    auto s = testing::three_joint_solution(task);
    task.robot.module_length = 0.30;  // longer than link 2
    const std::string sheet = modsynth::output::build_sheet(task, s);
    CHECK(sheet.find("| actuator module (default: HEBI X8) | 3 |") != std::string::npos);
    CHECK(sheet.find("**Warning:** link 1") != std::string::npos);
    CHECK(sheet.find("**Warning:** link 2") != std::string::npos);
    CHECK(sheet.find("**Warning:** link 3") == std::string::npos);
}

TEST_CASE("modules and tubes stack in z, the rod reaching the table", "[output]") {
    modsynth::task::RobotSpec spec;
    const double d = 0.03175, h = 0.045;
    CHECK(modsynth::output::output_face_height(spec, d, 0) == Approx(h));
    CHECK(modsynth::output::output_face_height(spec, d, 2) == Approx(3 * h + 2 * d));
    CHECK(modsynth::output::tube_axis_height(spec, d, 1) == Approx(2 * h + d + d / 2));
    CHECK(modsynth::output::ee_rod_length(spec, d, 2) == Approx(2 * h + 2 * d));
}

TEST_CASE("the build sheet shows a hostile task name as text, never as markup",
          "[output][escape]") {
    auto task = testing::two_joint_task();
    task.name =
        "<script>alert('x')</script> `rm -rf` | a | b\n# Injected\r\n]]> \"q\" [l](u) *e* "
        "&amp;\x01";
    const auto s = testing::two_joint_solution(task);
    const std::string sheet = modsynth::output::build_sheet(task, s);
    const std::string title = sheet.substr(0, sheet.find('\n'));
    CHECK(title.rfind("# Build sheet: ", 0) == 0);
    // Every character of the name survives, escaped, on the title line.
    CHECK(title.find("&lt;script&gt;alert(") == std::string::npos);
    CHECK(title.find("&lt;script&gt;alert\\(&#39;x&#39;\\)&lt;\\/script&gt;") != std::string::npos);
    CHECK(title.find("\\`rm \\-rf\\` \\| a \\| b") != std::string::npos);
    CHECK(title.find("\\]\\]&gt; &quot;q&quot; \\[l\\]\\(u\\) \\*e\\* &amp;amp\\;") !=
          std::string::npos);
    CHECK(sheet.find("<script") == std::string::npos);
    CHECK(sheet.find("\n# Injected") == std::string::npos);
    CHECK(sheet.find('\r') == std::string::npos);
    CHECK(sheet.find('\x01') == std::string::npos);
    for (std::size_t i = sheet.find('`'); i != std::string::npos; i = sheet.find('`', i + 1))
        CHECK(sheet[i - 1] == '\\');
    CHECK(title.find(" | a") == std::string::npos);
}

TEST_CASE("the build sheet lists the chosen modules and warns of an overloaded joint", "[output]") {
    const auto task = testing::two_joint_task();
    auto s = testing::two_joint_solution(task);
    // Without a choice the sheet has no modules section. Names are
    // Markdown-escaped (X8\\-16 renders as X8-16).
    CHECK(modsynth::output::build_sheet(task, s).find("## Modules") == std::string::npos);
    modsynth::hardware::ModuleSelection sel;
    sel.checked = true;
    sel.joints.resize(2);
    sel.joints[0].module = "X8-16";
    sel.joints[0].mass = 0.5;
    sel.joints[0].peak_margin = -3.25;
    sel.joints[0].family = "hebi-x";
    sel.joints[1].module = "XM430-W350";
    sel.joints[1].family = "dynamixel-x";
    sel.joints[1].cost = 289.90;
    sel.joints[1].mass = 0.335;
    sel.joints[1].peak_margin = 1.5;
    sel.joints[1].carries = true;
    sel.total_mass = 0.835;
    sel.cost =
        "cost: 1 x X8-16: cost unknown, 1 x XM430-W350 = $289.90; total $289.90 plus the "
        "modules of unknown cost";
    sel.overloaded_joint = 1;
    sel.message = "joint 1 is overloaded: no allowed module carries it";
    s.modules = sel;
    const std::string sheet = modsynth::output::build_sheet(task, s);
    CHECK(sheet.find("## Modules") != std::string::npos);
    CHECK(sheet.find("**Warning:** joint 1 is overloaded") != std::string::npos);
    // Each module with its family and cost; the parts bill under the table.
    CHECK(sheet.find("| 1 | X8\\-16 **(overloaded)** | hebi\\-x | unknown | 0.500 |") !=
          std::string::npos);
    CHECK(sheet.find("| -3.250 |") != std::string::npos);
    CHECK(sheet.find("| 2 | XM430\\-W350 | dynamixel\\-x | 289.90 | 0.335 |") != std::string::npos);
    CHECK(sheet.find("| X8\\-16 | hebi\\-x | 1 | unknown | unknown |") != std::string::npos);
    CHECK(sheet.find("| XM430\\-W350 | dynamixel\\-x | 1 | 289.90 | 289.90 |") !=
          std::string::npos);
    CHECK(sheet.find("0.835 kg in all; total cost $289.90 plus the modules of unknown cost.") !=
          std::string::npos);
}
