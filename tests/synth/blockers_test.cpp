#include <catch2/catch.hpp>

#include <modsynth/synth/blockers.h>

using namespace modsynth;

TEST_CASE("what stopped the candidates is said by joint count, most often first", "[synth]") {
    task::Task t;
    for (int j = 0; j < 50; ++j)
        t.trajectory.push_back(geometry::make_line({0.5 + 0.01 * j, 0.0}, {0.51 + 0.01 * j, 0.0}));
    synth::Blockers b;
    CHECK(b.empty());
    b.not_converged(2);
    b.out_of_reach(3, 11, true);
    for (int k = 0; k < 3; ++k) b.obstacle(3, 0, 1, 3 + 10 * k);
    b.obstacle(3, 0, 2, 40);
    b.obstacle(3, 4, 2, 7);
    b.self_collision(3, 9);
    b.no_travel(3, 49);
    CHECK_FALSE(b.empty());
    // Ties in the order of kinds (obstacles first), at most four a count.
    CHECK(b.describe(t) ==
          "with 2 joints: refinements that did not converge (1); "
          "with 3 joints: obstacles[0] in the way of links 2 and 3 (4, at trajectory[3] to "
          "trajectory[40]), obstacles[4] in the way of link 3 (1, at trajectory[7]), the tool "
          "too near its own links (1, at trajectory[9]), out of reach in the transitions (1, "
          "after trajectory[11])");
}
