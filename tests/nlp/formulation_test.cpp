#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include <modsynth/nlp/formulation.h>
#include <modsynth/nlp/solver.h>
#include <modsynth/io/task_io.h>

#include "../support/fixtures.h"

using namespace modsynth;

namespace {

nlp::ArmProblem rose_problem(nlp::SweptVolume swept) {
    static const task::Task rose = io::load_task(testing::source_path("tasks/rose.json"));
    nlp::ArmProblem p;
    p.task = &rose;
    p.skeleton.dof = 2;
    p.skeleton.elbow = -1;
    p.skeleton.base_region = 0;
    p.start.base = {0.0, 0.05};
    p.start.link_lengths = {0.5, 0.45};
    p.start.link_diameter = rose.robot.link_diameter;
    p.start.elbow = -1;
    p.swept = swept;
    p.horizon = 1.0;  // every obstacle at every point: all constraint kinds present
    for (int j = 0; j < static_cast<int>(rose.trajectory.size()); ++j)
        for (double s : {0.0, 0.03, 0.07}) p.points.push_back({j, s});
    return p;
}

// Central differences of the constraints and the Lagrangian's gradient
// against the exact Jacobian and Hessian, at a random point.
void check_derivatives(const nlp::QuadraticProgram& qp, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const int n = qp.num_variables(), m = qp.num_constraints();
    std::vector<double> x(n), lambda(m);
    for (int i = 0; i < n; ++i) x[i] = qp.start()[i] + 0.1 * u(rng);
    for (int k = 0; k < m; ++k) lambda[k] = u(rng);
    const double sigma = 0.7, h = 1e-6;

    const auto& js = qp.jacobian_structure();
    std::vector<double> jac(js.size());
    qp.eval_jacobian(x.data(), jac.data());
    std::vector<std::vector<double>> dense_jac(m, std::vector<double>(n, 0.0));
    for (std::size_t e = 0; e < js.size(); ++e) dense_jac[js[e].row][js[e].col] += jac[e];

    const auto& hs = qp.hessian_structure();
    std::vector<double> hess(hs.size());
    qp.eval_hessian(sigma, lambda.data(), hess.data());
    std::vector<std::vector<double>> dense_hess(n, std::vector<double>(n, 0.0));
    for (std::size_t e = 0; e < hs.size(); ++e) {
        dense_hess[hs[e].row][hs[e].col] += hess[e];
        if (hs[e].row != hs[e].col) dense_hess[hs[e].col][hs[e].row] += hess[e];
    }

    // Gradient of the Lagrangian sigma f + lambda . g, for the Hessian check.
    auto lagrangian_gradient = [&](const std::vector<double>& at) {
        std::vector<double> g(n, 0.0), grad(n), jv(js.size());
        qp.eval_gradient(at.data(), grad.data());
        qp.eval_jacobian(at.data(), jv.data());
        for (int i = 0; i < n; ++i) g[i] = sigma * grad[i];
        for (std::size_t e = 0; e < js.size(); ++e) g[js[e].col] += lambda[js[e].row] * jv[e];
        return g;
    };

    std::vector<double> gp(m), gm(m), grad(n);
    qp.eval_gradient(x.data(), grad.data());
    double worst_jac = 0.0, worst_hess = 0.0, worst_grad = 0.0;
    for (int i = 0; i < n; ++i) {
        std::vector<double> xp = x, xm = x;
        xp[i] += h;
        xm[i] -= h;
        qp.eval_constraints(xp.data(), gp.data());
        qp.eval_constraints(xm.data(), gm.data());
        for (int k = 0; k < m; ++k)
            worst_jac = std::max(worst_jac, std::abs((gp[k] - gm[k]) / (2 * h) - dense_jac[k][i]));
        worst_grad = std::max(worst_grad, std::abs((qp.eval_objective(xp.data()) - qp.eval_objective(xm.data())) /
                                                       (2 * h) -
                                                   grad[i]));
        const auto lp = lagrangian_gradient(xp), lm = lagrangian_gradient(xm);
        for (int r = 0; r < n; ++r)
            worst_hess = std::max(worst_hess, std::abs((lp[r] - lm[r]) / (2 * h) - dense_hess[r][i]));
    }
    CHECK(worst_grad < 1e-6);
    CHECK(worst_jac < 1e-6);
    CHECK(worst_hess < 1e-6);
}

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
    qp.set_objective(nlp::Quadratic{}.add(5.0).add(x, x, 1.0).add(x, -4.0).add(y, y, 1.0).add(y, -2.0));
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

TEST_CASE("refinement of the rose finds a shorter robot that keeps its constraints", "[nlp][slow]") {
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
