#include <modsynth/explanation/explanation.h>
#include <modsynth/explanation/wall_changes.h>
#include <modsynth/geometry/distance.h>
#include <modsynth/io/task_io.h>
#include <modsynth/prove/no_go.h>
#include <modsynth/prove/obstacle_proof.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "../support/fixtures.h"

using namespace modsynth;
using geometry::Vec2;

namespace {

task::Task load(const std::string& name) {
    return io::load_task(testing::source_path("tasks/infeasible/" + name + ".task.json"));
}

int index_in(const task::TaskPart& part) {
    REQUIRE(part.kind() == task::TaskPart::Kind::Obstacle);
    return part.index();
}

// The two obstacles a widening names, from "widen the gap between
// obstacles[i] and obstacles[j] ...".
std::pair<int, int> widened_pair(const std::string& change) {
    const auto a = change.find("obstacles["), b = change.find("obstacles[", a + 1);
    return {std::stoi(change.substr(a + 10)), std::stoi(change.substr(b + 10))};
}

double gap(const task::Task& t, int i, int j) {
    return (t.obstacles[i].center - t.obstacles[j].center).norm() - t.obstacles[i].radius -
           t.obstacles[j].radius;
}

}  // namespace

TEST_CASE("every change offered against a wall or a detour breaks its proof", "[walls]") {
    for (const std::string name : {"ring-around-path", "sieve-around-path", "long-wall"}) {
        INFO(name);
        const task::Task t = load(name);
        const auto proof = prove::prove_obstacle_infeasible(t);
        REQUIRE(proof);
        const auto kinds = explanation::wall_changes(t, *proof);
        REQUIRE(kinds.size() == 3);
        for (const auto& kind : kinds) {
            CHECK_FALSE(kind.empty());
            for (const auto& c : kind) {
                INFO(c.change);
                CHECK_FALSE(prove::prove_obstacle_infeasible(c.changed));
            }
        }
        // Removal: the obstacle of the core nearest the straight way from the
        // base region to the path point kept out whose removal breaks it
        // (the wall opens where the arm would pass); among as near, the
        // smallest.
        const auto& removal = kinds[0].at(0);
        CHECK(removal.change.rfind("remove " + task::to_string(removal.part), 0) == 0);
        const int k = index_in(removal.part);
        CHECK(removal.changed.obstacles.size() + 1 == t.obstacles.size());
        const auto off_the_way = [&](int i) {
            double near = 1e300;
            const auto way = [&](int region, const geometry::Vec2& point) {
                const auto& r = t.base_regions[region];
                near = std::min(near, geometry::point_segment(t.obstacles[i].center,
                                                              0.5 * (r.min + r.max), point));
            };
            if (proof->separation)
                for (const auto& w : proof->separation->walls) way(w.base_region, w.point);
            if (proof->geodesic)
                for (const auto& d : proof->geodesic->detours) way(d.base_region, d.point);
            return std::round(near * 1000.0);
        };
        for (const auto& part : proof->core) {
            if (part.kind() != task::TaskPart::Kind::Obstacle) continue;
            const int i = index_in(part);
            const bool before =
                off_the_way(i) < off_the_way(k) ||
                (off_the_way(i) == off_the_way(k) && t.obstacles[i].radius < t.obstacles[k].radius);
            if (!before) continue;
            task::Task without = t;
            without.obstacles.erase(without.obstacles.begin() + i);
            CHECK(prove::prove_obstacle_infeasible(without));  // one nearer would not do
        }
        // Widening: the gap is at least the tube (plus the margin) afterwards,
        // and what it asks for is needed: half the move leaves the proof.
        const auto& widening = kinds[1].at(0);
        CHECK(widening.change.rfind("widen the gap between", 0) == 0);
        const auto [i, j] = widened_pair(widening.change);
        CHECK(gap(widening.changed, i, j) >=
              t.robot.link_diameter + explanation::kGapMargin - 1e-9);
        CHECK(gap(t, i, j) < t.robot.link_diameter);
        if (widening.change.find(" further from ") != std::string::npos) {
            const int moved = index_in(widening.part);
            task::Task half = t;
            half.obstacles[moved].center =
                0.5 * (t.obstacles[moved].center + widening.changed.obstacles[moved].center);
            const double still = gap(half, i, j);
            if (still < t.robot.link_diameter) CHECK(prove::prove_obstacle_infeasible(half));
        }
        // Moving the base region keeps its size.
        const auto& move = kinds[2].at(0);
        CHECK(move.part == task::TaskPart::base_regions());
        CHECK(move.change.rfind("move base_regions[", 0) == 0);
        for (std::size_t r = 0; r < t.base_regions.size(); ++r) {
            const Vec2 before = t.base_regions[r].max - t.base_regions[r].min;
            const Vec2 after = move.changed.base_regions[r].max - move.changed.base_regions[r].min;
            CHECK((before - after).norm() < 1e-9);
        }
    }
}

TEST_CASE("a gap as wide as the tube plus the margin lets a ring's proof go", "[walls][property]") {
    // The ring's first pair, pulled apart by exactly what the widening asks:
    // no longer a wall; pulled apart by a millimetre less than the overlap
    // needs: still one.
    const task::Task t = load("ring-around-path");
    const auto proof = prove::prove_obstacle_infeasible(t);
    REQUIRE(proof);
    REQUIRE(proof->separation);
    const auto& w = proof->separation->walls.at(0);
    const auto kinds = explanation::wall_changes(t, *proof, 100);
    for (const auto& c : kinds[1]) {
        const auto [i, j] = widened_pair(c.change);
        INFO(c.change);
        const double overlap_depth =
            t.robot.link_diameter - gap(t, i, j);  // how far the no-go discs overlap
        REQUIRE(overlap_depth > 0.0);
        if (c.change.find(" further from ") == std::string::npos) continue;
        const int moved = index_in(c.part);
        const int other = moved == i ? j : i;
        const Vec2 u = (t.obstacles[moved].center - t.obstacles[other].center).normalized();
        task::Task short_of = t;
        short_of.obstacles[moved].center += (overlap_depth - 0.001) * u;
        if (std::find(w.cycle.begin(), w.cycle.end(), moved) != w.cycle.end())
            CHECK(prove::prove_obstacle_infeasible(short_of));
    }
}

TEST_CASE("explain suggests removing an obstacle, widening a gap and moving the base region",
          "[walls][explain][slow]") {
    for (const std::string name : {"ring-around-path", "long-wall"}) {
        INFO(name);
        const task::Task t = load(name);
        const auto proof = explanation::prove_infeasible(t, 10.0);
        REQUIRE(proof.proved);
        const auto suggestions = explanation::suggest_relaxations(t, proof.core, 2.0, 60.0);
        const auto with = [&](const std::string& start) {
            return std::find_if(suggestions.begin(), suggestions.end(),
                                [&](const auto& r) { return r.change.rfind(start, 0) == 0; });
        };
        for (const std::string kind :
             {"remove obstacles[", "widen the gap", "move base_regions["}) {
            INFO(kind);
            const auto it = with(kind);
            REQUIRE(it != suggestions.end());
            CHECK_FALSE(prove::prove_obstacle_infeasible(std::get<task::Task>(it->relaxed)));
            CHECK_FALSE(
                explanation::prove_infeasible(std::get<task::Task>(it->relaxed), 10.0).proved);
        }
    }
}
