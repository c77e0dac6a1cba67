// The fitting's work is bounded whatever the curve: curves below what it
// resolves are refused at once, every step advances, and a deadline stops
// it.
#include <catch2/catch.hpp>
#include <functional>
#include <string>

#include <modsynth/drawing/biarc_fit.h>
#include <modsynth/drawing/import.h>
#include <modsynth/task/input_error.h>

namespace {

using namespace modsynth::drawing;
using modsynth::task::InputError;

std::string message_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

BSpline spline_at_scale(double s, const Vec2& from = Vec2::Zero()) {
    BSpline b;
    b.degree = 3;
    b.control = {from, from + Vec2(s, 2 * s), from + Vec2(2 * s, -s), from + Vec2(3 * s, 0)};
    b.weights = {1, 1, 1, 1};
    b.knots = {0, 0, 0, 0, 1, 1, 1, 1};
    return b;
}

}  // namespace

TEST_CASE("fit: a curve below the resolution is refused at once", "[drawing][fit]") {
    // Squared distances across these underflow: the fitting once spun on them.
    for (double s : {1e-163, 1e-200, 1e-300, 1e-10}) {
        INFO(s);
        CHECK_THAT(message_of([&] {
                       fit_curve({"SPLINE #1", {spline_at_scale(s)}}, 1e-4, 5000);
                   }),
                   Catch::Contains("SPLINE #1") && Catch::Contains("m across once placed") &&
                       Catch::Contains("--scale"));
    }
    // Just above it, it fits.
    CHECK(!fit_curve({"s", {spline_at_scale(1e-7)}}, 1e-4, 5000).primitives.empty());
    // A tiny piece inside a curve of size is its chord, folded away.
    const FittedCurve f = fit_curve(
        {"c", {LineSegment{Vec2(0, 0), Vec2(0.1, 0)}, spline_at_scale(1e-12, Vec2(0.1, 0))}}, 1e-4,
        5000);
    REQUIRE(f.primitives.size() == 1);
    CHECK((f.primitives[0].end - Vec2(0.1 + 3e-12, 0)).norm() <= 1e-15);
}

TEST_CASE("import: placements too small to resolve are refused at once", "[drawing][fit]") {
    const std::string one =
        R"(<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100"><path id="c" d="M 10,50 C 30,10 70,90 90,50"/></svg>)";
    for (const auto& placement : {Placement{std::nullopt, 1e-200, std::nullopt, 0.0},
                                  Placement{1e-300, std::nullopt, std::nullopt, 0.0},
                                  Placement{std::nullopt, 1e-300, Vec2(0.5, 0.5), 30.0}}) {
        ImportOptions o;
        o.placement = placement;
        CHECK_THAT(message_of([&] { import_drawing(one, DrawingFormat::Svg, o); }),
                   Catch::Contains("path#c") && Catch::Contains("across once placed"));
    }
}

TEST_CASE("fit: a deadline stops the fitting", "[drawing][fit]") {
    const Curve c{"path#w",
                  {CubicBezier{Vec2(0, 0), Vec2(0.1, 0.3), Vec2(0.2, -0.3), Vec2(0.3, 0)}}};
    CHECK_THROWS_WITH(fit_curve(c, 1e-6, 5000, Clock::now()),
                      Catch::Contains("time limit") && Catch::Contains("fitting path#w"));
    ImportOptions o;
    o.deadline = Clock::now();
    const std::string one =
        R"(<svg xmlns="http://www.w3.org/2000/svg"><path d="M 10,50 C 30,10 70,90 90,50"/></svg>)";
    CHECK_THROWS_AS(import_drawing(one, DrawingFormat::Svg, o), ImportTimeout);
}

TEST_CASE("fit: a curve of cusps everywhere ends, refused or fitted", "[drawing][fit]") {
    // A spline whose control points double back on each other: no biarc
    // spans much of it, so the walk falls back to splitting again and again.
    BSpline b;
    b.degree = 3;
    for (int i = 0; i < 400; ++i) b.control.push_back(Vec2(1e-3 * (i % 2), 1e-3 * (i % 3)));
    b.weights.assign(b.control.size(), 1.0);
    for (int i = 0; i < 4; ++i) b.knots.push_back(0.0);
    for (std::size_t i = 1; i + 3 < b.control.size(); ++i) b.knots.push_back(double(i));
    for (int i = 0; i < 4; ++i) b.knots.push_back(double(b.control.size() - 3));
    const std::string m = message_of([&] { fit_curve({"zigzag", {b}}, 1e-9, 200); });
    CHECK_THAT(m, Catch::Contains("zigzag"));
}

TEST_CASE("import: a drawing past the primitives a task may have says so", "[drawing][fit][slow]") {
    std::string lines;
    for (int i = 0; i < 5001; ++i)
        lines += "<line x1=\"" + std::to_string(i % 90) + "\" y1=\"" + std::to_string(i / 90) +
                 "\" x2=\"" + std::to_string(i % 90) + ".5\" y2=\"" + std::to_string(i / 90) +
                 "\"/>";
    const std::string text =
        R"(<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100">)" +
        lines + "</svg>";
    ImportOptions o;
    o.keep_order = true;
    const std::string m = message_of([&] { import_drawing(text, DrawingFormat::Svg, o); });
    // The whole drawing is counted, and no tolerance helps lines.
    CHECK_THAT(m, Catch::Contains("(document): the drawing needs 5001 primitives at --tolerance "
                                  "0.0001 m, more than the 5000 a task may hold: simplify it"));
    // Curves need fewer at a larger tolerance: the least that fits is named.
    std::string ellipses;
    for (int i = 0; i < 120; ++i) {
        ellipses +=
            "<ellipse cx=\"50\" cy=\"50\" rx=\"40\" ry=\"" + std::to_string(5 + 0.5 * i) + "\"/>";
    }
    const std::string curved =
        R"(<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100">)" +
        ellipses + "</svg>";
    o.tolerance = 2e-6;
    CHECK_THAT(
        message_of([&] { import_drawing(curved, DrawingFormat::Svg, o); }),
        Catch::Matches(".*the drawing needs [0-9]+ primitives at --tolerance 2e-06 m, more "
                       "than the 5000 a task may hold: --tolerance [0-9.e-]+ fits it \\([0-9]+ "
                       "primitives\\), or simplify the drawing"));
    // A curve that alone needs more than are left is told how many were.
    CHECK_THAT(message_of([] {
                   fit_curve(
                       {"path#w",
                        {CubicBezier{Vec2(0, 0), Vec2(0.1, 0.3), Vec2(0.2, -0.3), Vec2(0.3, 0)}}},
                       1e-9, 3);
               }),
               Catch::Contains("path#w: needs more than the 3 primitives left for it"));
}
