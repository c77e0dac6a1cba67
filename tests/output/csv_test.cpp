#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

#include <modsynth/output/csv.h>

#include "output_fixtures.h"

namespace testing = modsynth::testing;
using modsynth::synth::Solution;

namespace {

std::vector<std::string> split(const std::string& text, char sep) {
    std::vector<std::string> out;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, sep)) out.push_back(item);
    return out;
}

/// Every row holds its sample's time, angles, phase and primitive.
void check_rows(const Solution& s) {
    const auto lines = split(modsynth::output::trajectory_csv(s), '\n');
    REQUIRE(lines.size() == s.samples.size() + 1);
    const int dof = s.robot.dof();
    for (std::size_t i = 0; i < s.samples.size(); ++i) {
        const auto& x = s.samples[i];
        const auto cells = split(lines[i + 1], ',');
        REQUIRE(cells.size() == static_cast<std::size_t>(dof + 3));
        CHECK(std::stod(cells[0]) == Approx(x.t).margin(1e-6));
        for (int k = 0; k < dof; ++k) CHECK(std::stod(cells[1 + k]) == Approx(x.q[k]).margin(1e-9));
        CHECK(cells[dof + 1] ==
              (x.phase == modsynth::control::Phase::Trace ? "trace" : "transition"));
        CHECK(std::stoi(cells[dof + 2]) == x.primitive);
    }
}

}  // namespace

TEST_CASE("the CSV has one row per sample of a 2-joint motion", "[output]") {
    const Solution s = testing::two_joint_solution(testing::two_joint_task());
    const std::string csv = modsynth::output::trajectory_csv(s);
    CHECK(csv.rfind("t,q1,q2,phase,primitive\n", 0) == 0);
    check_rows(s);
}

TEST_CASE("the CSV of a 3-joint motion has three angles and transitions", "[output]") {
    const Solution s = testing::three_joint_solution(testing::three_joint_task());
    const std::string csv = modsynth::output::trajectory_csv(s);
    CHECK(csv.rfind("t,q1,q2,q3,phase,primitive\n", 0) == 0);
    CHECK(csv.find(",transition,0\n") != std::string::npos);
    check_rows(s);
}

TEST_CASE("the CSV keeps angles unwrapped", "[output]") {
    Solution s = testing::two_joint_solution(testing::two_joint_task());
    s.samples.resize(1);
    s.samples[0].q = {7.5, -9.25};
    const auto lines = split(modsynth::output::trajectory_csv(s), '\n');
    CHECK(lines[1] == "0.000000,7.500000000,-9.250000000,trace,0");
}
