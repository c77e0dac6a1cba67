#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include <modsynth/io/task_io.h>
#include <modsynth/nlp/formulation.h>
#include <modsynth/nlp/solver.h>

#include "../support/arm_problems.h"
#include "../support/derivative_check.h"
#include "../support/fixtures.h"

using namespace modsynth;
using testing::check_derivatives;

namespace {

nlp::ArmProblem rose_problem(nlp::SweptVolume swept) { return testing::rose_arm_problem(swept); }

}  // namespace

TEST_CASE("refinement derivatives agree with finite differences", "[nlp][slow]") {
    for (auto swept : {nlp::SweptVolume::Sampled, nlp::SweptVolume::Over}) {
        const nlp::Formulation f = nlp::formulate(rose_problem(swept));
        INFO((swept == nlp::SweptVolume::Over ? "SV-over" : "sampled"));
        REQUIRE(f.program.num_variables() > 4 + 2 * 21);
        REQUIRE(f.program.num_constraints() > 3 * 21);
        check_derivatives(f.program, 7);
        check_derivatives(f.program, 11);
    }
}

TEST_CASE("the start point of a reachable robot satisfies link and elbow constraints", "[nlp]") {
    nlp::ArmProblem p = rose_problem(nlp::SweptVolume::Sampled);
    p.horizon = -1.0;  // leave obstacles out
    const nlp::Formulation f = nlp::formulate(p);
    CHECK(f.program.infeasibility(f.program.start().data()) < 1e-9);
}

TEST_CASE("Ipopt minimises a small quadratic program to its known optimum", "[nlp]") {
    // min (x - 2)^2 + (y - 1)^2  s.t.  x^2 + y^2 <= 1: the projection of
    // (2, 1) onto the unit disc, (2, 1) / sqrt(5).
    nlp::QuadraticProgram qp;
    const int x = qp.add_variable(-nlp::kInfinity, nlp::kInfinity, 0.0, "x");
    const int y = qp.add_variable(-nlp::kInfinity, nlp::kInfinity, 0.0, "y");
    qp.set_objective(
        nlp::Quadratic{}.add(5.0).add(x, x, 1.0).add(x, -4.0).add(y, y, 1.0).add(y, -2.0));
    qp.add_constraint(nlp::Quadratic{}.add(x, x, 1.0).add(y, y, 1.0), -nlp::kInfinity, 1.0, "disc");
    qp.finalize();
    const nlp::SolverResult r = nlp::minimize(qp, {});
    REQUIRE(r.usable());
    CHECK(r.x[x] == Approx(2.0 / std::sqrt(5.0)).margin(1e-6));
    CHECK(r.x[y] == Approx(1.0 / std::sqrt(5.0)).margin(1e-6));
    CHECK(r.objective == Approx(std::pow(std::sqrt(5.0) - 1.0, 2)).margin(1e-6));
}

TEST_CASE("an infeasible program is reported, not returned as a solution", "[nlp]") {
    nlp::QuadraticProgram qp;
    const int x = qp.add_variable(-1.0, 1.0, 0.0, "x");
    qp.set_objective(nlp::Quadratic{}.add(x, 1.0));
    qp.add_constraint(nlp::Quadratic{}.add(x, x, 1.0), 4.0, nlp::kInfinity, "x^2 >= 4");
    qp.finalize();
    const nlp::SolverResult r = nlp::minimize(qp, {});
    CHECK_FALSE(r.usable());
}

TEST_CASE("refinement of the rose finds a shorter robot that keeps its constraints",
          "[nlp][slow]") {
    nlp::ArmProblem p = rose_problem(nlp::SweptVolume::Sampled);
    p.horizon = 0.10;
    p.start.base = {-0.02, 0.007};  // a start clear of the obstacles
    p.start.link_lengths = {0.56, 0.47};
    const nlp::Formulation f = nlp::formulate(p);
    const nlp::SolverResult r = nlp::minimize(f.program, {});
    REQUIRE(r.usable());
    CHECK(f.program.infeasibility(r.x.data()) < 1e-6);
    const kinematics::Robot robot = nlp::robot_from(f, r.x);
    CHECK(robot.total_length() < 1.03);
    CHECK(robot.base.x() >= -0.05 - 1e-9);
    CHECK(robot.base.x() <= 0.10 + 1e-9);
}

TEST_CASE("three-joint refinement derivatives agree with finite differences", "[nlp]") {
    // Proximal poses, transitions bisected to the default depth and the EE
    // kept from link 1: the constraint kinds only three joints have.
    nlp::ArmProblem p = rose_problem(nlp::SweptVolume::Sampled);
    p.skeleton.dof = 3;
    p.start.link_lengths = {0.2, 0.35, 0.3};
    for (int j = 0; j < static_cast<int>(p.task->trajectory.size()); ++j)
        p.start.proximal_angles.push_back(0.3 + 0.05 * j);
    p.points.clear();
    for (int j = 0; j < static_cast<int>(p.task->trajectory.size()); j += 4)
        p.points.push_back({j, 0.02});
    const nlp::Formulation f = nlp::formulate(p);
    CHECK(f.proximal.size() == p.task->trajectory.size());
    int bisectors = 0;
    for (int k = 0; k < f.program.num_constraints(); ++k)
        bisectors += f.program.constraint_label(k).rfind("bisector", 0) == 0;
    // Two per pose, 2^3 - 1 poses per transition.
    CHECK(bisectors == 2 * 7 * static_cast<int>(p.task->trajectory.size() - 1));
    check_derivatives(f.program, 5);
}

TEST_CASE("a failed refinement names the constraints that stay violated", "[nlp]") {
    // An obstacle sits on the path itself: the EE must be there, so the
    // last link cannot keep its clearance at that point, whatever Ipopt does.
    static task::Task blocked = io::load_task(testing::source_path("tasks/rose.json"));
    const geometry::Vec2 on_path = geometry::point_at(blocked.trajectory[3], 0.02);
    blocked.obstacles.push_back({on_path, 0.01});
    const int obstacle = static_cast<int>(blocked.obstacles.size()) - 1;
    nlp::ArmProblem p = rose_problem(nlp::SweptVolume::Sampled);
    p.task = &blocked;
    p.points = {{3, 0.02}};
    const nlp::Formulation f = nlp::formulate(p);
    const nlp::SolverResult r = nlp::minimize(f.program, {});
    REQUIRE_FALSE(r.usable());
    INFO(r.message);
    CHECK(r.message.rfind("Ipopt status ", 0) == 0);
    const std::string expected = "clearance of link 2 to obstacles[" + std::to_string(obstacle) +
                                 "], trajectory[3] at 0.020000 m";
    CHECK(r.message.find("at the last iterate " + expected + " is violated by ") !=
          std::string::npos);
    // The worst violation is reported first, and it is a real one.
    const auto violated = f.program.violated(r.x.data(), 1e-9);
    REQUIRE_FALSE(violated.empty());
    CHECK(f.program.constraint_label(violated.front().constraint) == expected);
    CHECK(violated.front().amount > 1e-3);
}

TEST_CASE("violated constraints come worst first, ties in program order", "[nlp]") {
    nlp::QuadraticProgram qp;
    const int x = qp.add_variable(-10.0, 10.0, 0.0, "x");
    qp.add_constraint(nlp::Quadratic{}.add(x, 1.0), 1.0, nlp::kInfinity, "x >= 1");
    qp.add_constraint(nlp::Quadratic{}.add(x, 1.0), 3.0, nlp::kInfinity, "x >= 3");
    qp.add_constraint(nlp::Quadratic{}.add(x, 1.0), -nlp::kInfinity, 5.0, "x <= 5");
    qp.add_constraint(nlp::Quadratic{}.add(x, -1.0), -nlp::kInfinity, -1.0, "-x <= -1");
    qp.finalize();
    const double at = 0.0;
    const auto v = qp.violated(&at, 1e-9);
    REQUIRE(v.size() == 3);
    CHECK(qp.constraint_label(v[0].constraint) == "x >= 3");
    CHECK(v[0].amount == 3.0);
    CHECK(qp.constraint_label(v[1].constraint) == "x >= 1");
    CHECK(qp.constraint_label(v[2].constraint) == "-x <= -1");
    CHECK(qp.violated(&at, 5.0).empty());
}
