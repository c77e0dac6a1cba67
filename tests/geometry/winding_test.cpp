#include <catch2/catch.hpp>

#include <cmath>

#include <modsynth/geometry/winding.h>

using namespace modsynth;
using geometry::Vec2;

TEST_CASE("a primitive's turn round a point is the angle its chord sees, or a whole turn",
          "[geometry][winding]") {
    const Vec2 c(0.0, 0.0);
    CHECK(geometry::turning_angle(geometry::make_line({1.0, -1.0}, {1.0, 1.0}), c) ==
          Approx(geometry::kPi / 2.0));
    CHECK(geometry::turning_angle(geometry::make_circle({1.0, 0.0}, c, true), c) ==
          Approx(geometry::kTau));
    CHECK(geometry::turning_angle(geometry::make_circle({1.0, 0.0}, c, false), c) ==
          Approx(-geometry::kTau));
    // A circle beside the point turns back as far as it turns out.
    CHECK(geometry::turning_angle(geometry::make_circle({3.0, 0.0}, {2.0, 0.0}, true), c) ==
          Approx(0.0).margin(1e-12));
    // Three quarters of a circle, clockwise: from its centre, 3/4 of a turn;
    // from a point a hair inside it, 7/8 of a turn, not the 1/8 the other
    // way that its chord sees.
    const geometry::Primitive arc = geometry::make_arc({0.0, -1.0}, {1.0, 0.0}, {0.0, 0.0}, false);
    CHECK(geometry::turning_angle(arc, {0.0, 0.0}) == Approx(-1.5 * geometry::kPi));
    CHECK(geometry::turning_angle(arc, {-0.999999, 0.0}) ==
          Approx(-1.75 * geometry::kPi).epsilon(1e-5));
    CHECK(std::isnan(geometry::turning_angle(geometry::make_line({-1.0, 0.0}, {1.0, 0.0}), c)));
}
