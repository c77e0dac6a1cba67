#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include <modsynth/geometry/distance.h>
#include <modsynth/geometry/polygon.h>
#include <modsynth/geometry/primitive.h>
#include <modsynth/io/task_io.h>
#include <modsynth/kinematics/kinematics.h>
#include <modsynth/nlp/formulation.h>
#include <modsynth/nlp/solver.h>

#include "../support/derivative_check.h"
#include "../support/fixtures.h"

// The paper's swept-volume models (III-B, III-D) as the refinement encodes
// them, checked against the polygons rebuilt here from the solved robot.
using namespace modsynth;
using geometry::Vec2;
using testing::check_derivatives;

namespace {

const task::Task& rose() {
    static const task::Task t = io::load_task(testing::source_path("tasks/rose.json"));
    return t;
}

const task::Task& wipe_table() {
    static const task::Task t = io::load_task(testing::source_path("tasks/wipe-table.json"));
    return t;
}

// The paper's points: the ends, closest and farthest of every primitive
// relative to the point the distal pair turns about.
void paper_points(nlp::ArmProblem& p) {
    const task::Task& t = *p.task;
    p.points.clear();
    for (int j = 0; j < static_cast<int>(t.trajectory.size()); ++j) {
        const auto cp = geometry::critical_points(t.trajectory[j], p.start.tracing_origin(j));
        for (double s : {0.0, geometry::length(t.trajectory[j]), cp.closest.s, cp.farthest.s})
            p.points.push_back({j, s});
    }
}

nlp::ArmProblem rose_app() {
    nlp::ArmProblem p;
    p.task = &rose();
    p.skeleton.dof = 2;
    p.skeleton.elbow = -1;
    p.skeleton.base_region = 0;
    p.start.base = {-0.02, 0.007};
    p.start.link_lengths = {0.56, 0.47};
    p.start.link_diameter = rose().robot.link_diameter;
    p.start.elbow = -1;
    p.swept = nlp::SweptVolume::App;
    p.swept_only = true;
    paper_points(p);
    return p;
}

nlp::ArmProblem wipe_three_joints(nlp::SweptVolume swept) {
    nlp::ArmProblem p;
    p.task = &wipe_table();
    p.skeleton.dof = 3;
    p.skeleton.elbow = -1;
    p.skeleton.base_region = 0;
    p.start.base = {0.0, 0.02};
    p.start.link_lengths = {0.48, 0.11, 0.36};
    p.start.link_diameter = wipe_table().robot.link_diameter;
    p.start.elbow = -1;
    for (int j = 0; j < static_cast<int>(wipe_table().trajectory.size()); ++j)
        p.start.proximal_angles.push_back(1.2 + 0.3 * j);
    p.swept = swept;
    p.swept_only = true;
    paper_points(p);
    return p;
}

int count_labels(const nlp::Formulation& f, const std::string& prefix) {
    int n = 0;
    for (int k = 0; k < f.program.num_constraints(); ++k)
        n += f.program.constraint_label(k).rfind(prefix, 0) == 0;
    return n;
}

// SV^app rebuilt from the robot: the elbows at the problem's points about
// o_j, the arc between the two that bound the largest angular gap, and the
// pentagon (sector) and quadrilateral (arc) over it, as in III-D.
struct AppPolygons {
    std::vector<Vec2> sector, arc;
};

AppPolygons app_polygons(const nlp::ArmProblem& p, const kinematics::Robot& robot, int j) {
    const int a = robot.dof() - 2;
    const double ra = robot.link_lengths[a], rb = robot.link_lengths[a + 1];
    const Vec2 o = robot.tracing_origin(j);
    std::vector<double> angle;
    for (const auto& pt : p.points) {
        if (pt.primitive != j) continue;
        const Vec2 target = geometry::point_at(p.task->trajectory[j], pt.s);
        const Vec2 e = kinematics::elbow_towards(o, ra, rb, target, robot.elbow);
        angle.push_back(std::atan2(e.y() - o.y(), e.x() - o.x()));
    }
    std::sort(angle.begin(), angle.end());
    double gap = angle.front() + geometry::kTau - angle.back(), start = angle.front();
    for (std::size_t i = 1; i < angle.size(); ++i)
        if (angle[i] - angle[i - 1] > gap) {
            gap = angle[i] - angle[i - 1];
            start = angle[i];
        }
    const double span = geometry::kTau - gap, far = ra / std::cos(span / 4);
    const Vec2 p1 = o + ra * geometry::unit(start), p2 = o + ra * geometry::unit(start + span);
    const Vec2 c1 = o + far * geometry::unit(start + span / 4);
    const Vec2 c2 = o + far * geometry::unit(start + 3 * span / 4);
    AppPolygons out;
    out.sector = geometry::convex_hull({o, p1, c1, c2, p2});
    std::vector<Vec2> arc{p1, c1, c2, p2};
    const auto& prim = p.task->trajectory[j];
    const double len = geometry::length(prim);
    for (int i = 0; i <= 64; ++i) arc.push_back(geometry::point_at(prim, len * i / 64));
    out.arc = geometry::convex_hull(arc);
    return out;
}

}  // namespace

TEST_CASE("SV-app and 3-joint SV-over derivatives agree with finite differences", "[nlp]") {
    const nlp::Formulation app = nlp::formulate(rose_app());
    check_derivatives(app.program, 3);
    nlp::ArmProblem three = wipe_three_joints(nlp::SweptVolume::App);
    three.transition_depth = 1;
    check_derivatives(nlp::formulate(three).program, 5);
    three.swept = nlp::SweptVolume::Over;
    check_derivatives(nlp::formulate(three).program, 7);
}

TEST_CASE("SV-app: one separating line per obstacle, primitive and polygon", "[nlp]") {
    const nlp::Formulation f = nlp::formulate(rose_app());
    const int prims = static_cast<int>(rose().trajectory.size());
    const int obstacles = static_cast<int>(rose().obstacles.size());
    CHECK(count_labels(f, "SV unit link 1 ") == prims * obstacles);
    CHECK(count_labels(f, "SV unit link 2 ") == prims * obstacles);
    // The swept volume stands for the links at the paper's points: no
    // separating line per link and point.
    CHECK(count_labels(f, "clearance of link") == 0);
    // The arc's middle and both tangent corners, per primitive.
    CHECK(count_labels(f, "SV tangent ") == 4 * prims);
}

TEST_CASE("SV-app on the rose: the solved robot's pentagons keep clear of every obstacle",
          "[nlp]") {
    const nlp::ArmProblem p = rose_app();
    const nlp::Formulation f = nlp::formulate(p);
    const nlp::SolverResult r = nlp::minimize(f.program, {});
    REQUIRE(r.usable());
    const kinematics::Robot robot = nlp::robot_from(f, r.x);
    const double half = robot.link_diameter / 2;
    for (int j = 0; j < static_cast<int>(rose().trajectory.size()); ++j) {
        const AppPolygons sv = app_polygons(p, robot, j);
        for (const auto& ob : rose().obstacles) {
            INFO("primitive " << j << ", obstacle at " << ob.center.transpose());
            CHECK(geometry::disc_convex_polygon(ob.center, ob.radius, sv.sector) >=
                  half + p.margins.clearance - 1e-5);
            CHECK(geometry::disc_convex_polygon(ob.center, ob.radius, sv.arc) >=
                  half + p.margins.clearance - 1e-5);
        }
    }
}

TEST_CASE("SV-over with three joints: conv(disc(o_j, r_2), primitive j) keeps clear", "[nlp]") {
    nlp::ArmProblem p = wipe_three_joints(nlp::SweptVolume::Over);
    const nlp::Formulation f = nlp::formulate(p);
    const int prims = static_cast<int>(wipe_table().trajectory.size());
    CHECK(count_labels(f, "SV disc ") == prims * static_cast<int>(wipe_table().obstacles.size()));
    const nlp::SolverResult r = nlp::minimize(f.program, {});
    REQUIRE(r.usable());
    const kinematics::Robot robot = nlp::robot_from(f, r.x);
    for (int j = 0; j < prims; ++j) {
        const Vec2 o = robot.tracing_origin(j);
        std::vector<Vec2> pts;
        for (int i = 0; i < 128; ++i)
            pts.push_back(o + robot.link_lengths[1] * geometry::unit(geometry::kTau * i / 128));
        const auto& prim = wipe_table().trajectory[j];
        for (int i = 0; i <= 64; ++i)
            pts.push_back(geometry::point_at(prim, geometry::length(prim) * i / 64));
        const auto hull = geometry::convex_hull(pts);
        for (const auto& ob : wipe_table().obstacles) {
            INFO("primitive " << j << ", obstacle at " << ob.center.transpose());
            // The 128-gon lies inside the disc: the bound holds for it too.
            CHECK(geometry::disc_convex_polygon(ob.center, ob.radius, hull) >=
                  robot.link_diameter / 2 + p.margins.clearance - 1e-5);
            // The static proximal link keeps its own clearance.
            CHECK(geometry::disc_segment(ob.center, ob.radius, robot.base, o) >=
                  robot.link_diameter / 2 + p.margins.clearance - 1e-5);
        }
    }
}
