#include <modsynth/explanation/explanation.h>
#include <modsynth/geometry/distance.h>
#include <modsynth/io/solution_io.h>
#include <modsynth/io/task_io.h>
#include <modsynth/prove/geodesic_reach.h>
#include <modsynth/prove/obstacle_proof.h>
#include <modsynth/prove/separation.h>
#include <modsynth/synth/synthesizer.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <random>

#include "../support/fixtures.h"
#include "../support/witness_checker.h"

using namespace modsynth;
using geometry::Vec2;

namespace {

task::Task load(const std::string& name) {
    return io::load_task(testing::source_path("tasks/infeasible/" + name + ".task.json"));
}

std::vector<int> core_obstacles(const std::vector<task::TaskPart>& core) {
    std::vector<int> out;
    for (const auto& p : core)
        if (p.kind() == task::TaskPart::Kind::Obstacle) out.push_back(p.index());
    return out;
}

// n posts of radius r evenly on a circle of radius ring around c.
std::vector<task::Obstacle> ring(const Vec2& c, double ring, int n, double r, double phase = 0.0) {
    std::vector<task::Obstacle> out;
    for (int k = 0; k < n; ++k)
        out.push_back({c + ring * geometry::unit(phase + geometry::kTau * k / n), r});
    return out;
}

// A small circle to trace around (0.5, 0.3), a base plate at the origin.
task::Task ringed(const std::vector<task::Obstacle>& posts) {
    task::Task t;
    t.name = "ringed";
    t.trajectory.push_back(geometry::make_circle({0.58, 0.30}, {0.50, 0.30}, true));
    t.obstacles = posts;
    t.base_regions.push_back({{-0.05, -0.05}, {0.05, 0.05}});
    return t;
}

// A vertical wall of overlapping posts at x = 0.5 from y = -half to +half,
// the base plate at the origin, a short stroke at x = 1.
task::Task walled(double half, double max_link) {
    task::Task t;
    t.name = "walled";
    t.trajectory.push_back(geometry::make_line({1.0, -0.1}, {1.0, 0.1}));
    const int n = static_cast<int>(std::ceil(2 * half / 0.09)) + 1;
    for (int k = 0; k < n; ++k)
        t.obstacles.push_back({{0.5, -half + 2 * half * k / (n - 1)}, 0.05});
    t.base_regions.push_back({{-0.05, -0.05}, {0.05, 0.05}});
    t.robot.max_link_length = max_link;
    return t;
}

}  // namespace

TEST_CASE("a ring of posts around the path is a closed wall", "[walls]") {
    const task::Task t = load("ring-around-path");
    const auto proof = prove::prove_obstacle_infeasible(t);
    REQUIRE(proof);
    REQUIRE(proof->separation);
    CHECK_FALSE(proof->geodesic);
    CHECK(testing::check_separation_witness(t, *proof->separation).empty());
    // The two decoys (12, 13) are no part of it; the posts overlap, so the
    // tube's diameter is not either.
    CHECK(core_obstacles(proof->core) == std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11});
    CHECK(std::find(proof->core.begin(), proof->core.end(),
                    task::TaskPart::robot(task::RobotKey::LinkDiameter)) == proof->core.end());
    CHECK(
        proof->message.rfind(
            "obstacles 0-11 form a closed wall around trajectory[0]; the base region is outside it",
            0) == 0);
    // A base region that reaches across the wall, where only the post's no-go
    // disc covers its inner part: still separated, cell by cell.
    task::Task across = t;
    across.base_regions = {{{0.66, 0.28}, {0.78, 0.32}}};
    const auto still = prove::prove_obstacle_infeasible(across);
    REQUIRE(still);
    REQUIRE(still->separation);
    CHECK(testing::check_separation_witness(across, *still->separation).empty());
    // Past the disc, into the ring: not any more.
    across.base_regions = {{{0.60, 0.28}, {0.78, 0.32}}};
    CHECK_FALSE(prove::prove_obstacle_infeasible(across));
}

TEST_CASE("an open sieve whose gaps are narrower than the tube is a closed wall", "[walls]") {
    const task::Task t = load("sieve-around-path");
    const auto proof = prove::prove_obstacle_infeasible(t);
    REQUIRE(proof);
    REQUIRE(proof->separation);
    CHECK(testing::check_separation_witness(t, *proof->separation).empty());
    CHECK(core_obstacles(proof->core) == std::vector<int>{2, 3, 4, 5, 6, 7, 8, 9, 10, 11});
    CHECK(std::find(proof->core.begin(), proof->core.end(),
                    task::TaskPart::robot(task::RobotKey::LinkDiameter)) != proof->core.end());
    // Posts apart in the task, closed only by the tube: a thinner one passes.
    task::Task thin = t;
    thin.robot.link_diameter = 0.02;
    CHECK_FALSE(prove::prove_obstacle_infeasible(thin));
}

TEST_CASE("a long wall whose way around is beyond reach", "[walls]") {
    const task::Task t = load("long-wall");
    const auto proof = prove::prove_obstacle_infeasible(t);
    REQUIRE(proof);
    REQUIRE(proof->geodesic);
    CHECK_FALSE(proof->separation);
    CHECK(testing::check_geodesic_witness(t, *proof->geodesic) == "");
    const auto& d = proof->geodesic->detours.at(0);
    CHECK(d.lower_bound > 3.0);
    // The straight way is 1 m: only the wall makes it long.
    CHECK(geometry::point_box(d.point, t.base_regions[0].min, t.base_regions[0].max) < 1.0);
    const auto core = core_obstacles(proof->core);
    CHECK(core.size() >= 20);
    CHECK(std::find(core.begin(), core.end(), 45) == core.end());  // the decoy
    CHECK(std::find(proof->core.begin(), proof->core.end(),
                    task::TaskPart::robot(task::RobotKey::MaxLinkLength)) != proof->core.end());
    CHECK(proof->message.find("3 links of at most 1.00 m reach 3.00 m") != std::string::npos);
}

TEST_CASE("removing any obstacle of a core breaks its proof", "[walls]") {
    for (const char* name : {"ring-around-path", "sieve-around-path", "long-wall"}) {
        INFO(name);
        const task::Task t = load(name);
        const auto proof = prove::prove_obstacle_infeasible(t);
        REQUIRE(proof);
        const auto core = core_obstacles(proof->core);
        const bool separation = proof->separation.has_value();
        CHECK((separation ? prove::prove_separation(t, core).has_value()
                          : prove::prove_geodesic_reach(t, core).has_value()));
        for (int k : core) {
            std::vector<int> fewer;
            for (int i : core)
                if (i != k) fewer.push_back(i);
            INFO("without obstacles[" << k << "]");
            CHECK_FALSE((separation ? prove::prove_separation(t, fewer).has_value()
                                    : prove::prove_geodesic_reach(t, fewer).has_value()));
            // And in the task itself: only the rest of the core is left.
            task::Task rest = t;
            rest.obstacles.clear();
            for (int i : fewer) rest.obstacles.push_back(t.obstacles[i]);
            CHECK_FALSE(prove::prove_obstacle_infeasible(rest));
        }
    }
}

TEST_CASE("the witnesses travel in the solution JSON and still check after reading", "[walls]") {
    for (const char* name : {"ring-around-path", "long-wall"}) {
        INFO(name);
        const task::Task t = load(name);
        const synth::Solution s = synth::synthesize(t, {});
        REQUIRE(s.status == synth::Status::Infeasible);
        const auto back = io::parse_solution(io::to_json(s)).solution;
        REQUIRE(back.explanation.core == s.explanation.core);
        if (s.explanation.separation) {
            REQUIRE(back.explanation.separation);
            CHECK(testing::check_separation_witness(t, *back.explanation.separation).empty());
            CHECK(back.explanation.separation->walls[0].cycle ==
                  s.explanation.separation->walls[0].cycle);
        } else {
            REQUIRE(back.explanation.geodesic);
            CHECK(testing::check_geodesic_witness(t, *back.explanation.geodesic).empty());
            CHECK(back.explanation.geodesic->detours[0].lower_bound ==
                  s.explanation.geodesic->detours[0].lower_bound);
        }
    }
}

TEST_CASE("explain states the wall", "[walls]") {
    const task::Task t = load("sieve-around-path");
    const auto proof = explanation::prove_infeasible(t, 10.0);
    REQUIRE(proof.proved);
    CHECK(proof.message.find("form a closed wall") != std::string::npos);
    REQUIRE(proof.separation);
}

TEST_CASE("rings: a wall exactly when every gap is narrower than the tube", "[walls][property]") {
    std::mt19937 rng(15);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int walls = 0, open = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const int n = 6 + static_cast<int>(u(rng) * 10);
        const double ring_r = 0.18 + 0.1 * u(rng);
        const double post = 0.02 + 0.04 * u(rng);
        auto posts = ring({0.5, 0.3}, ring_r, n, post, u(rng));
        // Jitter the radii so that the gaps differ.
        for (auto& p : posts) p.radius *= 0.9 + 0.2 * u(rng);
        task::Task t = ringed(posts);
        double widest = 0.0;
        for (int k = 0; k < n; ++k) {
            const auto& a = posts[k];
            const auto& b = posts[(k + 1) % n];
            widest = std::max(widest, (a.center - b.center).norm() - a.radius - b.radius);
        }
        // The path keeps clear of the posts (else the task is invalid).
        bool valid = true;
        for (const auto& p : posts)
            valid = valid && geometry::point_primitive(p.center, t.trajectory[0]) > p.radius + 0.02;
        if (!valid || std::abs(widest - t.robot.link_diameter) < 1e-6) continue;
        const bool closed = widest < t.robot.link_diameter;
        INFO("trial " << trial << ": widest gap " << widest);
        const auto proof = prove::prove_obstacle_infeasible(t);
        CHECK(proof.has_value() == closed);
        if (proof && proof->separation)
            CHECK(testing::check_separation_witness(t, *proof->separation).empty());
        // The base moved inside the ring: base and path on one side.
        task::Task inside = t;
        inside.base_regions = {{{0.47, 0.27}, {0.53, 0.33}}};
        CHECK_FALSE(prove::prove_obstacle_infeasible(inside));
        (closed ? walls : open) += 1;
    }
    CHECK(walls > 30);
    CHECK(open > 30);
}

TEST_CASE("walls: a detour proof exactly when the way around is beyond reach",
          "[walls][property][slow]") {
    std::mt19937 rng(16);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int proved = 0, not_proved = 0;
    for (int trial = 0; trial < 40; ++trial) {
        const double half = 0.5 + 1.5 * u(rng);
        const double max_link = 0.5 + 0.8 * u(rng);
        const task::Task t = walled(half, max_link);
        const double reach = 3 * max_link;
        const double r = 0.05 + t.robot.link_diameter / 2;
        // Every way crosses the line x = 0.5 above or below the wall; the
        // union ends at half + r. From the nearest corner of the plate to the
        // nearest path point through that end: a lower bound. Through a
        // point well clear of the end: an upper bound.
        const Vec2 corner(0.05, 0.05), q(1.0, 0.1), start(1.0, -0.1);
        const double lower =
            (Vec2(0.5, half + r) - corner).norm() + (q - Vec2(0.5, half + r)).norm();
        const double upper = (Vec2(0.5, half + r + 0.05) - Vec2(0.05, -0.05)).norm() +
                             (start - Vec2(0.5, half + r + 0.05)).norm();
        if (lower > reach + 1e-6 || upper < reach - 1e-6) {
            const bool far = lower > reach;
            INFO("trial " << trial << ": half " << half << ", reach " << reach);
            const auto proof = prove::prove_obstacle_infeasible(t);
            if (far) {
                REQUIRE(proof);
                REQUIRE(proof->geodesic);
                CHECK(proof->geodesic->detours[0].lower_bound > reach);
                CHECK(testing::check_geodesic_witness(t, *proof->geodesic).empty());
                // With every obstacle, the bound is at least the way over the end.
                const auto discs = prove::no_go_discs(t, prove::all_obstacles(t));
                CHECK(prove::geodesic_distance(discs, t.base_regions[0].min, t.base_regions[0].max,
                                               proof->geodesic->detours[0].point) >= lower - 1e-9);
                ++proved;
            } else {
                CHECK_FALSE(proof);
                ++not_proved;
            }
        }
    }
    CHECK(proved > 5);
    CHECK(not_proved > 5);
}

TEST_CASE("the detour bound never exceeds a way the roadmap finds", "[walls][property]") {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 12; ++trial) {
        task::Task t;
        for (int k = 0; k < 8; ++k) t.obstacles.push_back({{u(rng), u(rng)}, 0.03 + 0.1 * u(rng)});
        const task::BaseRegion region{{-0.3, -0.3}, {-0.2, -0.1}};
        const Vec2 p(1.2, 1.1);
        const auto discs = prove::no_go_discs(t, prove::all_obstacles(t));
        const double bound = prove::geodesic_distance(discs, region.min, region.max, p);
        const double found = testing::roadmap_distance(t, region, p, 64);
        INFO("trial " << trial);
        CHECK(bound <= found + 1e-9);
        CHECK(found <= bound * 1.01 + 1e-6);  // and it is tight
    }
}

TEST_CASE("no planted feasible task is proved infeasible by its obstacles", "[walls]") {
    int checked = 0;
    for (const char* dir :
         {"tests/fixtures/planted-obstacles", "tests/fixtures/planted", "tests/fixtures/valid"}) {
        for (const auto& e : std::filesystem::directory_iterator(testing::source_path(dir))) {
            const std::string path = e.path().string();
            if (path.size() < 5 || path.substr(path.size() - 5) != ".json" ||
                path.find(".expect.") != std::string::npos ||
                path.find("/ir-") != std::string::npos || path.find("/io-") != std::string::npos)
                continue;
            task::Task t;
            try {
                t = io::load_task(path);
            } catch (const std::exception&) {
                continue;  // not a task (a solution, a fixture of another kind)
            }
            INFO(path);
            CHECK_FALSE(prove::prove_obstacle_infeasible(t));
            ++checked;
        }
    }
    CHECK(checked >= 40);
}
