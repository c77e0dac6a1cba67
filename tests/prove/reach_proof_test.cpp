#include <catch2/catch.hpp>

#include <modsynth/prove/reach_proof.h>
#include <modsynth/task/strokes.h>

using namespace modsynth;

namespace {

/// A line from (x0, 0) to (x1, 0), a base region around the origin, links of
/// at most 1 m.
task::Task line_task(double x0, double x1, std::vector<int> dof = {2, 3}) {
    task::Task t;
    t.name = "reach";
    t.trajectory.push_back(geometry::make_line({x0, 0.0}, {x1, 0.0}));
    t.base_regions.push_back({{-0.1, -0.1}, {0.1, 0.1}});
    t.robot.dof = std::move(dof);
    t.robot.max_link_length = 1.0;
    return t;
}

}  // namespace

TEST_CASE("a primitive beyond the longest arm from every base is a proof with a minimal core",
          "[synth][reach_proof]") {
    // The far end is 3.5 m from the origin, 3.4 m from the nearest base: a
    // 3-link arm of 1 m links reaches 3 m.
    const auto core = prove::out_of_reach_core(line_task(1.5, 3.5));
    REQUIRE(core);
    CHECK(*core == std::vector<task::TaskPart>{task::TaskPart::robot(task::RobotKey::MaxLinkLength),
                                               task::TaskPart::base_regions(),
                                               task::TaskPart::trajectory(0)});
    // Two joints reach 2 m: a line ending 2.2 m from the nearest base is out.
    CHECK(prove::out_of_reach_core(line_task(0.5, 2.3, {2})));
    CHECK_FALSE(prove::out_of_reach_core(line_task(0.5, 2.3, {2, 3})));
}

TEST_CASE("a primitive some base reaches is no proof", "[synth][reach_proof]") {
    // 3.05 m from the origin but 2.95 m from the base region's near corner.
    CHECK_FALSE(prove::out_of_reach_core(line_task(1.0, 3.05)));
    // Out of reach of the first region, not of the second.
    task::Task two = line_task(1.5, 3.5);
    two.base_regions.push_back({{1.0, -0.1}, {1.2, 0.1}});
    CHECK_FALSE(prove::out_of_reach_core(two));
    // The base anywhere: nothing is out of reach.
    task::Task anywhere = line_task(1.5, 3.5);
    anywhere.base_regions.clear();
    CHECK_FALSE(prove::out_of_reach_core(anywhere));
}

TEST_CASE("the core names the primitive farthest out of reach", "[synth][reach_proof]") {
    // Out to 4 m and on to 5 m: both lines are out of reach, the second
    // farther.
    task::Task t = line_task(0.5, 1.0);
    t.trajectory.push_back(geometry::make_line({1.0, 0.0}, {4.0, 0.0}));
    t.trajectory.push_back(geometry::make_line({4.0, 0.0}, {5.0, 0.0}));
    t.trajectory.push_back(geometry::make_line({5.0, 0.0}, {1.0, 0.0}));
    const auto core = prove::out_of_reach_core(t);
    REQUIRE(core);
    CHECK(core->back() == task::TaskPart::primitive(t, 2));
}
