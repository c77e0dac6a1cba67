#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <variant>

#include <nlohmann/json.hpp>

#include <modsynth/drawing/surface.h>
#include <modsynth/io/spatial_task_io.h>
#include <modsynth/task/input_error.h>

namespace {

using namespace modsynth::drawing;
using modsynth::geometry::Primitive;
using modsynth::geometry::Primitive3;
using modsynth::task::InputError;
namespace g = modsynth::geometry;

constexpr double kPi = g::kPi;

/// A tangent-continuous stroke (a line, a quarter arc turning left, a line,
/// a half arc turning right) and a circle of its own, centred near the
/// origin as an import places a drawing on a surface.
std::vector<Chain> sample_strokes() {
    Chain a;
    a.push_back(g::make_line(Vec2(-0.06, -0.03), Vec2(0.0, -0.03)));
    a.push_back(g::make_arc(Vec2(0.0, -0.03), Vec2(0.02, -0.01), Vec2(0.0, -0.01), true));
    a.push_back(g::make_line(Vec2(0.02, -0.01), Vec2(0.02, 0.01)));
    a.push_back(g::make_arc(Vec2(0.02, 0.01), Vec2(0.06, 0.01), Vec2(0.04, 0.01), false));
    Chain b;
    b.push_back(g::make_circle(Vec2(-0.02, 0.03), Vec2(-0.03, 0.03), true));
    // Lines along, round and across the axis once wrapped.
    Chain c;
    c.push_back(g::make_line(Vec2(-0.05, 0.04), Vec2(-0.05, 0.06)));
    c.push_back(g::make_line(Vec2(-0.05, 0.06), Vec2(0.05, 0.06)));
    c.push_back(g::make_line(Vec2(0.05, 0.06), Vec2(0.0, 0.1)));
    // Nearly level: a helix would climb less than 5 mm a turn.
    c.push_back(g::make_line(Vec2(0.0, 0.1), Vec2(-0.06, 0.1005)));
    return {a, b, c};
}

/// The placed stroke as the drawing's stroke carried exactly: every
/// placed point within `tol` of the exact image of the drawing, and back.
template <class Map>
void check_follows(const Chain& drawn, const Chain3& placed, const Map& map, double tol) {
    std::vector<Vec3> exact;
    for (const Primitive& p : drawn)
        for (int k = 0; k <= 400; ++k) exact.push_back(map(g::point_at(p, g::length(p) * k / 400)));
    double spacing = 0.0;
    for (std::size_t i = 1; i < exact.size(); ++i)
        spacing = std::max(spacing, (exact[i] - exact[i - 1]).norm());
    for (const Vec3& q : exact) {
        double d = INFINITY;
        for (const Primitive3& p : placed) d = std::min(d, g::nearest(p, q).distance);
        CHECK(d <= tol);
    }
    for (const Primitive3& p : placed) {
        for (int k = 0; k <= 50; ++k) {
            const Vec3 q = g::point_at(p, g::length(p) * k / 50);
            double d = INFINITY;
            for (const Vec3& e : exact) d = std::min(d, (e - q).norm());
            CHECK(d - spacing / 2 <= tol);
        }
    }
}

/// Consecutive primitives meet within 1e-9 m, and their tangents turn by
/// at most max_turn (radians) where they meet.
void check_connected(const Chain3& placed, double max_turn) {
    for (std::size_t j = 1; j < placed.size(); ++j) {
        CHECK((g::start_point(placed[j]) - g::end_point(placed[j - 1])).norm() <= 1e-9);
        const Vec3 t0 = g::tangent_at(placed[j - 1], g::length(placed[j - 1]));
        const Vec3 t1 = g::tangent_at(placed[j], 0.0);
        CHECK(std::acos(std::clamp(t0.dot(t1), -1.0, 1.0)) <= max_turn);
    }
}

}  // namespace

TEST_CASE("plane_surface: directions unit and perpendicular within 1e-3, named otherwise",
          "[drawing][surface]") {
    const PlaneSurface s = plane_surface({0.4, 0, 0.3, 0, 1, 0, -0.7071, 0, 0.7071});
    CHECK(s.u.norm() == Approx(1.0).margin(1e-15));
    CHECK(s.v.norm() == Approx(1.0).margin(1e-15));
    CHECK(std::abs(s.u.dot(s.v)) <= 1e-15);
    CHECK((s.v - Vec3(-1, 0, 1) / std::sqrt(2.0)).norm() <= 1e-12);
    auto refused = [](const std::vector<double>& n, const std::string& why) {
        try {
            plane_surface(n);
            FAIL("accepted");
        } catch (const InputError& e) {
            CHECK(e.part() == "--plane");
            CHECK_THAT(e.what(), Catch::Contains(why));
        }
    };
    refused({0, 0, 0, 1, 0, 0, 0, 2, 0}, "V (0, 2, 0) is not a unit vector");
    refused({0, 0, 0, 0.99, 0, 0, 0, 1, 0}, "U (0.99, 0, 0) is not a unit vector");
    refused({0, 0, 0, 1, 0, 0, 0.1, 0.995, 0}, "not perpendicular");
    refused({0, 0, 0, 1, 0, 0, 0, 1}, "expected 9 numbers");
    refused({0, 0, 0, 1, 0, 0, 0, 1, NAN}, "finite");
}

TEST_CASE("cylinder_surface: the axis, the radius, the side it faces", "[drawing][surface]") {
    const CylinderSurface s = cylinder_surface({0.5, 0, 0.2, 0, 0, 3, 0.06}, Vec3::Zero());
    CHECK((s.axis - Vec3::UnitZ()).norm() <= 1e-15);
    CHECK((s.facing - Vec3(-1, 0, 0)).norm() <= 1e-15);
    // The drawing's centre on the side towards the base, its x to the right
    // seen from there (y along the axis up).
    CHECK((surface_point(s, Vec2::Zero()) - Vec3(0.44, 0, 0.2)).norm() <= 1e-15);
    CHECK(surface_direction(s, Vec2::Zero(), Vec2::UnitX()).dot(Vec3(0, -1, 0)) == Approx(1.0));
    // An axis through the base: facing world x.
    CHECK(
        (cylinder_surface({0, 0, 0, 0, 0, 1, 0.1}, Vec3(0, 0, 1)).facing - Vec3::UnitX()).norm() <=
        1e-15);
    for (const auto& [numbers, why] :
         {std::pair<std::vector<double>, std::string>{{0, 0, 0, 0, 0, 0, 0.1}, "no direction"},
          {{0, 0, 0, 0, 0, 1, 0}, "radius 0 must be positive"},
          {{0, 0, 0, 0, 0, 1, -1}, "must be positive"},
          {{0, 0, 0, 0, 0, 1}, "expected 7 numbers"}}) {
        try {
            cylinder_surface(numbers, Vec3::Zero());
            FAIL("accepted");
        } catch (const InputError& e) {
            CHECK(e.part() == "--cylinder");
            CHECK_THAT(e.what(), Catch::Contains(why));
        }
    }
}

TEST_CASE("place_on_plane: exact, on the plane, connected and tangent-continuous",
          "[drawing][surface]") {
    const PlaneSurface s = plane_surface({0.45, 0.1, 0.3, 0, 1, 0, -0.6, 0, 0.8});
    const Vec3 normal = s.u.cross(s.v);
    const auto strokes = sample_strokes();
    const PlacedStrokes placed = place_on_plane(strokes, s);
    REQUIRE(placed.strokes.size() == strokes.size());
    CHECK(placed.deviation == 0.0);
    for (std::size_t k = 0; k < strokes.size(); ++k) {
        REQUIRE(placed.strokes[k].size() == strokes[k].size());
        for (std::size_t j = 0; j < strokes[k].size(); ++j) {
            const Primitive& p = strokes[k][j];
            const Primitive3& q = placed.strokes[k][j];
            CHECK(g::length(q) == Approx(g::length(p)).epsilon(1e-12));
            for (int i = 0; i <= 20; ++i) {
                const double at = g::length(p) * i / 20;
                const Vec3 x = g::point_at(q, at);
                CHECK(std::abs((x - s.origin).dot(normal)) <= 1e-9);
                CHECK((x - surface_point(s, g::point_at(p, at))).norm() <= 1e-9);
                const Vec2 t = g::tangent_at(p, at);
                CHECK((g::tangent_at(q, at) - (t.x() * s.u + t.y() * s.v)).norm() <= 1e-9);
            }
        }
        check_connected(placed.strokes[k], k == 2 ? kPi : 1e-9);
    }
}

TEST_CASE("place_on_cylinder: lines along the axis, round it and across it, curves fitted",
          "[drawing][surface]") {
    const CylinderSurface s = cylinder_surface({0.45, 0, 0.25, 0, 0, 1, 0.05}, Vec3::Zero());
    const auto strokes = sample_strokes();
    constexpr double tol = 5e-5;
    const PlacedStrokes placed = place_on_cylinder(strokes, s, tol, 5000);
    REQUIRE(placed.strokes.size() == 3);
    CHECK(placed.deviation <= tol);
    const auto map = [&](const Vec2& p) { return surface_point(s, p); };
    const auto off_axis = [&](const Vec3& x) {
        const Vec3 r = x - s.center;
        return (r - r.dot(s.axis) * s.axis).norm();
    };
    // The third stroke's lines map exactly: a line, an arc about the axis,
    // a helix; the nearly level one is fitted.
    const Chain3& c = placed.strokes[2];
    REQUIRE(c.size() >= 4);
    CHECK(std::holds_alternative<g::Line3>(c[0]));
    REQUIRE(std::holds_alternative<g::Arc3>(c[1]));
    CHECK((std::get<g::Arc3>(c[1]).turn.axis - s.axis).norm() <= 1e-15);
    CHECK(std::get<g::Arc3>(c[1]).sweep == Approx(0.1 / 0.05));
    REQUIRE(std::holds_alternative<g::Helix3>(c[2]));
    const auto& h = std::get<g::Helix3>(c[2]);
    CHECK(h.turns == Approx(0.05 / (2 * kPi * 0.05)));
    CHECK(h.pitch * h.turns == Approx(0.04));
    CHECK_FALSE(h.turn.ccw);
    for (int k = 0; k < 3; ++k) {
        for (int i = 0; i <= 40; ++i) {
            const Vec3 x = g::point_at(c[k], g::length(c[k]) * i / 40);
            CHECK(std::abs(off_axis(x) - 0.05) <= 1e-9);
        }
    }
    for (std::size_t k = 0; k < strokes.size(); ++k) {
        check_follows(strokes[k], placed.strokes[k], map, tol);
        for (const Primitive3& p : placed.strokes[k]) {
            for (int i = 0; i <= 20; ++i)
                CHECK(std::abs(off_axis(g::point_at(p, g::length(p) * i / 20)) - 0.05) <= tol);
        }
    }
    // Tangent-continuous where the drawing is: all of the first stroke, the
    // circle, and within each fitted line of the third (its corners are
    // the drawing's).
    check_connected(placed.strokes[0], 1e-6);
    check_connected(placed.strokes[1], 1e-6);
    check_connected(placed.strokes[2], kPi);
    CHECK((g::start_point(placed.strokes[1].front()) - g::end_point(placed.strokes[1].back()))
              .norm() <= 1e-9);
    const Vec3 tc0 = g::tangent_at(placed.strokes[1].front(), 0.0);
    const Vec3 tc1 = g::tangent_at(placed.strokes[1].back(), g::length(placed.strokes[1].back()));
    CHECK((tc0 - tc1).norm() <= 1e-6);
    for (std::size_t j = 4; j < c.size(); ++j) {
        const Vec3 t0 = g::tangent_at(c[j - 1], g::length(c[j - 1]));
        CHECK((t0 - g::tangent_at(c[j], 0.0)).norm() <= 1e-6);
    }

    // A task of them is valid as the spatial reader checks it.
    modsynth::task::SpatialTask t;
    for (const Chain3& stroke : placed.strokes) {
        t.stroke_starts.push_back(static_cast<int>(t.trajectory.size()));
        t.trajectory.insert(t.trajectory.end(), stroke.begin(), stroke.end());
    }
    CHECK_NOTHROW(modsynth::io::parse_spatial_task(modsynth::io::to_json(t)));
}

TEST_CASE("place_on_cylinder: a drawing wider than the circumference is refused",
          "[drawing][surface]") {
    const auto strokes = sample_strokes();
    CHECK(drawing_width(strokes) == Approx(0.12));
    const CylinderSurface thin = cylinder_surface({0, 0, 0, 0, 0, 1, 0.019}, Vec3::UnitX());
    try {
        place_on_cylinder(strokes, thin, 1e-4, 5000);
        FAIL("accepted");
    } catch (const InputError& e) {
        CHECK(e.part() == "--cylinder");
        CHECK_THAT(e.what(),
                   Catch::Contains("0.12 m wide, more than the cylinder's circumference"));
    }
    // Exactly the circumference: a line round it is a whole circle.
    const CylinderSurface snug =
        cylinder_surface({0, 0, 0, 0, 0, 1, 0.12 / (2 * kPi)}, Vec3::UnitX());
    const PlacedStrokes round =
        place_on_cylinder({{g::make_line(Vec2(-0.06, 0), Vec2(0.06, 0))}}, snug, 1e-4, 5000);
    REQUIRE(round.strokes[0].size() == 1);
    REQUIRE(std::holds_alternative<g::Arc3>(round.strokes[0][0]));
    CHECK(std::get<g::Arc3>(round.strokes[0][0]).sweep == Approx(2 * kPi));
    CHECK_THROWS_AS(
        place_on_cylinder(strokes, cylinder_surface({0, 0, 0, 0, 0, 1, 0.05}, Vec3::UnitX()), 1e-4,
                          3),
        InputError);
}
