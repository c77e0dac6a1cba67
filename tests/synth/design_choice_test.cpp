#include <modsynth/synth/design_choice.h>

#include <catch2/catch.hpp>

#include <limits>
#include <stdexcept>
#include <vector>

using modsynth::synth::choose_design;
using modsynth::synth::DesignMerit;

TEST_CASE("the shortest design is returned when no near-tie passes farther away",
          "[synth][design_choice]") {
    const std::vector<DesignMerit> d{{0.50, 0.10}, {0.40, 0.05}, {0.41, 0.20}};
    CHECK(choose_design(d, 5e-4) == 1);  // 0.41 m is 10 mm longer: no tie
    CHECK(choose_design(d, 0.02) == 2);  // within 20 mm it is, and clearer
    CHECK(choose_design(std::vector<DesignMerit>{{0.3, 0.0}}, 5e-4) == 0);
    CHECK(choose_design(d, 0.0) == 1);
}

TEST_CASE("a design a fraction of a millimetre longer wins by clearance",
          "[synth][design_choice]") {
    // The elbow-down robot of a planted task and its elbow-up twin.
    const std::vector<DesignMerit> d{{0.34072, 0.1575}, {0.34064, 0.0320}};
    CHECK(choose_design(d, 5e-4) == 0);
    CHECK(choose_design(d, 5e-5) == 1);
}

TEST_CASE("near-ties are measured from the shortest, so a chain cannot drift longer",
          "[synth][design_choice]") {
    // Each is 0.4 mm longer than the last and clearer: only the first two are
    // within 0.5 mm of the shortest.
    const std::vector<DesignMerit> d{
        {0.5000, 0.01}, {0.5004, 0.02}, {0.5008, 0.03}, {0.5012, 0.04}};
    CHECK(choose_design(d, 5e-4) == 1);
}

TEST_CASE("clearances closer than the tie go to the shorter, then the earlier design",
          "[synth][design_choice]") {
    const double inf = std::numeric_limits<double>::infinity();  // no obstacles
    CHECK(choose_design(std::vector<DesignMerit>{{0.5002, inf}, {0.5000, inf}}, 5e-4) == 1);
    CHECK(choose_design(std::vector<DesignMerit>{{0.5, 0.1}, {0.5, 0.1}}, 5e-4) == 0);
    CHECK(choose_design(std::vector<DesignMerit>{{0.5, 0.1}, {0.6, 0.1}, {0.5, 0.1}}, 5e-4) == 0);
    // 0.5 mm longer for a hundredth of a millimetre more clearance: no.
    CHECK(choose_design(std::vector<DesignMerit>{{0.37207, 0.02199}, {0.37257, 0.02200}}, 5e-4) ==
          0);
    // Against the clearest, not each other: 0.1004 is within 0.5 mm of
    // 0.1008 but 0.1000 is not.
    CHECK(choose_design(
              std::vector<DesignMerit>{{0.5000, 0.1000}, {0.5001, 0.1004}, {0.5002, 0.1008}},
              5e-4) == 1);
}

TEST_CASE("no design to choose from is an error", "[synth][design_choice]") {
    CHECK_THROWS_AS(choose_design(std::vector<DesignMerit>{}, 5e-4), std::invalid_argument);
}

TEST_CASE("between designs tied in length and clearance the quicker motion wins",
          "[synth][design_choice]") {
    // Same length to a builder, same clearance: 8.3 s against 7.1 s.
    const std::vector<DesignMerit> d{{0.5340, 0.0023, 8.3}, {0.5342, 0.0022, 7.1}};
    CHECK(choose_design(d, 5e-4) == 1);
    // Motions within half a per cent are equally quick: length decides.
    const std::vector<DesignMerit> e{{0.5340, 0.0023, 8.30}, {0.5342, 0.0022, 8.27}};
    CHECK(choose_design(e, 5e-4) == 0);
    // Time never buys length beyond the tie, nor clearance.
    const std::vector<DesignMerit> f{{0.5340, 0.0023, 8.3}, {0.9672, 0.0023, 4.5}};
    CHECK(choose_design(f, 5e-4) == 0);
    const std::vector<DesignMerit> g{{0.5340, 0.0500, 8.3}, {0.5341, 0.0023, 4.5}};
    CHECK(choose_design(g, 5e-4) == 0);
    // Designs not timed (infinity) leave the choice to length.
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<DesignMerit> h{{0.5342, 0.0023, inf}, {0.5340, 0.0023, inf}};
    CHECK(choose_design(h, 5e-4) == 1);
}
