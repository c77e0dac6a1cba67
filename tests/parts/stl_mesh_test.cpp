#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <modsynth/parts/external_tool.h>
#include <modsynth/parts/hole_spacing.h>
#include <modsynth/parts/printed_parts.h>
#include <modsynth/parts/stl_mesh.h>

using namespace modsynth::parts;
using modsynth::geometry::Vec3;

namespace {

/// An axis-aligned box, outward facing.
Mesh box(const Vec3& lo, const Vec3& hi) {
    const auto v = [&](int i) {
        return Vec3(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
    };
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    Mesh m;
    for (const auto& q : quads) {
        m.triangles.push_back({v(q[0]), v(q[1]), v(q[2])});
        m.triangles.push_back({v(q[0]), v(q[2]), v(q[3])});
    }
    return m;
}

/// The wall of a vertical hole (facing into it) of diameter d at (x, y),
/// from z 0 to h, as a 96-gon: what a section through a plate meets.
void add_hole_wall(Mesh& m, double x, double y, double d, double h) {
    const int n = 96;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * M_PI * i / n, b = 2 * M_PI * ((i + 1) % n) / n;
        const Vec3 p(x + d / 2 * std::cos(a), y + d / 2 * std::sin(a), 0);
        const Vec3 q(x + d / 2 * std::cos(b), y + d / 2 * std::sin(b), 0);
        const Vec3 up(0, 0, h);
        m.triangles.push_back({p, p + up, q});
        m.triangles.push_back({q, p + up, q + up});
    }
}

LinkDesign design(double length) {
    modsynth::hardware::Actuator a;
    a.name = "X5-9";
    a.dimensions = {0.110, 0.073, 0.031};
    const ModuleMount m = module_mount(a, {});
    return link_design(1, length, m, m, 0.0095, 13.0, PrintSettings{});
}

}  // namespace

TEST_CASE("a closed box: no bad edges, its volume, centre and inertia", "[parts]") {
    Mesh m = box(Vec3(0, 0, 0), Vec3(2, 1, 1));
    CHECK(bad_edges(m) == 0);
    const MassProperties p = mass_properties(m);
    CHECK(p.volume == Approx(2.0));
    CHECK((p.centroid - Vec3(1, 0.5, 0.5)).norm() == Approx(0.0).margin(1e-12));
    // A 2 x 1 x 1 box of density 1: Izz = m (a^2 + b^2) / 12.
    CHECK(p.inertia(2, 2) == Approx(2.0 * (4 + 1) / 12.0));
    CHECK(p.inertia(0, 0) == Approx(2.0 * (1 + 1) / 12.0));
    CHECK(p.inertia(0, 1) == Approx(0.0).margin(1e-12));
    // A missing facet opens three edges; a flipped one misorients three.
    Mesh open = m;
    open.triangles.pop_back();
    CHECK(bad_edges(open) == 3);
    Mesh flipped = m;
    std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
    CHECK(bad_edges(flipped) > 0);
}

TEST_CASE("STL text is read, and what is not STL is refused by name", "[parts]") {
    const std::string text =
        "solid t\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n"
        "   vertex 0 1 0\n  endloop\n endfacet\nendsolid t\n";
    const Mesh m = parse_stl(text, "t.stl");
    REQUIRE(m.triangles.size() == 1);
    CHECK(m.triangles[0][1] == Vec3(1, 0, 0));
    CHECK_THROWS_WITH(parse_stl("hello", "x.stl"), Catch::Contains("x.stl"));
    CHECK_THROWS_WITH(read_stl("/nonexistent/x.stl"), Catch::Contains("/nonexistent/x.stl"));
}

TEST_CASE("a section finds each hole's centre and diameter", "[parts]") {
    Mesh m = box(Vec3(-20, -20, 0), Vec3(200, 20, 6));
    add_hole_wall(m, 0, 0, 14.6, 6);
    add_hole_wall(m, 152.4, 0, 5.2, 6);
    const auto loops = section_loops(m, 2.9);
    REQUIRE(loops.size() == 3);
    int holes = 0;
    for (const auto& l : loops) {
        if (std::abs(l.diameter - 14.6) < 0.02) {
            ++holes;
            CHECK(l.centre.norm() == Approx(0.0).margin(1e-9));
        }
        if (std::abs(l.diameter - 5.2) < 0.02) {
            ++holes;
            CHECK(l.centre.x() == Approx(152.4));
        }
    }
    CHECK(holes == 2);
}

TEST_CASE("the spacing check measures the axes in the mesh", "[parts]") {
    const LinkDesign l = design(0.1524);
    const auto plate_with_holes = [&](double axis_x) {
        Mesh m = box(Vec3(-30, -30, 0), Vec3(260, 30, l.beam.plate * 1000));
        add_hole_wall(m, 0, 0, l.horn_bore * 1000, l.beam.plate * 1000);
        add_hole_wall(m, axis_x, 0, l.axis_hole * 1000, l.beam.plate * 1000);
        return m;
    };
    const SpacingCheck good = check_spacing(plate_with_holes(152.45), l);
    CHECK(good.ok);
    CHECK(good.measured == Approx(0.15245));
    CHECK(good.message.find("152.4500 mm apart") != std::string::npos);
    const SpacingCheck off = check_spacing(plate_with_holes(152.6), l);
    CHECK_FALSE(off.ok);
    CHECK(off.message.find("more than 0.1 mm off") != std::string::npos);
    // No hole of the axis's diameter: said, not guessed.
    Mesh none = box(Vec3(-30, -30, 0), Vec3(260, 30, l.beam.plate * 1000));
    add_hole_wall(none, 0, 0, l.horn_bore * 1000, l.beam.plate * 1000);
    const SpacingCheck missing = check_spacing(none, l);
    CHECK_FALSE(missing.ok);
    CHECK(missing.message.find("0 loops of the axis hole's diameter") != std::string::npos);
}

TEST_CASE("a link's mass is its mesh's volume at the printed density", "[parts]") {
    // 100 x 20 x 10 mm of PLA at a solid fraction of 0.7.
    const Mesh m = box(Vec3(0, -10, 0), Vec3(100, 10, 10));
    const PrintSettings s;
    const auto body = link_body(m, s);
    CHECK(body.mass == Approx(20e-6 * 1240.0 * 0.7));
    CHECK(body.com == Approx(0.05));
    CHECK(body.inertia == Approx(body.mass * (0.1 * 0.1 + 0.02 * 0.02) / 12.0));
    // As a solid, in m in the frame it is drawn in: the centre off the bed,
    // the whole tensor, its moment about z the same.
    const auto solid = link_solid(m, s);
    CHECK(solid.mass == Approx(body.mass));
    CHECK((solid.com - Vec3(0.05, 0.0, 0.005)).norm() < 1e-12);
    CHECK(solid.inertia(2, 2) == Approx(body.inertia));
    CHECK(solid.inertia(0, 0) == Approx(body.mass * (0.02 * 0.02 + 0.01 * 0.01) / 12.0));
    CHECK(solid.inertia(1, 1) == Approx(body.mass * (0.1 * 0.1 + 0.01 * 0.01) / 12.0));
    CHECK(std::abs(solid.inertia(0, 1)) < 1e-12);
}

TEST_CASE("admesh's report is read, and anything it fixed fails the check", "[parts]") {
    const std::string clean = R"(
========= Facet Status ========== Original ============ Final ====
Number of facets                 :   144                 144
Facets with 1 disconnected edge  :     0                   0
Total disconnected facets        :     0                   0
=== Processing Statistics ===     ===== Other Statistics =====
Number of parts       :     1        Volume   :  964.883911
Degenerate facets     :     0
Edges fixed           :     0
Facets removed        :     0
Facets added          :     0
Facets reversed       :     0
Backwards edges       :     0
Normals fixed         :     0
)";
    const AdmeshReport r = parse_admesh(clean);
    CHECK(r.parsed);
    CHECK(r.closed_manifold());
    std::string holed = clean;
    holed.replace(holed.find("Facets added          :     0"), 29, "Facets added          :     2");
    CHECK_FALSE(parse_admesh(holed).closed_manifold());
    CHECK_FALSE(parse_admesh("admesh: cannot open").parsed);
    CHECK_FALSE(parse_admesh("admesh: cannot open").closed_manifold());
}

TEST_CASE("an external program is run with a time limit, and a missing one is said", "[parts]") {
    const ToolRun ok = run_tool({"sh", "-c", "echo hello; exit 3"}, 10.0);
    CHECK(ok.started);
    CHECK(ok.exit_code == 3);
    CHECK(ok.output == "hello\n");
    const ToolRun missing = run_tool({"modsynth-no-such-program"}, 10.0);
    CHECK_FALSE(missing.started);
    CHECK_FALSE(missing.ok());
    const ToolRun slow = run_tool({"sleep", "5"}, 0.2);
    CHECK(slow.timed_out);
    CHECK_FALSE(on_path("modsynth-no-such-program"));
    CHECK(on_path("sh"));
}

TEST_CASE("a cut through an open surface is no loop", "[parts]") {
    Mesh m = box(Vec3(0, 0, 0), Vec3(2, 1, 1));
    m.triangles.erase(m.triangles.begin() + 4, m.triangles.begin() + 6);  // one side wall
    CHECK(section(m, 0.5).empty());
    CHECK(section(box(Vec3(0, 0, 0), Vec3(2, 1, 1)), 0.5).size() == 1);
}
