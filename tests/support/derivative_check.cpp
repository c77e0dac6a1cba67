#include "derivative_check.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace modsynth::testing {

DerivativeErrors derivative_errors(const nlp::QuadraticProgram& qp, unsigned seed) {
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
        worst_grad = std::max(
            worst_grad,
            std::abs((qp.eval_objective(xp.data()) - qp.eval_objective(xm.data())) / (2 * h) -
                     grad[i]));
        const auto lp = lagrangian_gradient(xp), lm = lagrangian_gradient(xm);
        for (int r = 0; r < n; ++r)
            worst_hess =
                std::max(worst_hess, std::abs((lp[r] - lm[r]) / (2 * h) - dense_hess[r][i]));
    }
    return {worst_grad, worst_jac, worst_hess};
}

void check_derivatives(const nlp::QuadraticProgram& qp, unsigned seed, double tolerance) {
    const DerivativeErrors e = derivative_errors(qp, seed);
    INFO("seed " << seed << ", " << qp.num_variables() << " variables, " << qp.num_constraints()
                 << " constraints");
    CHECK(e.gradient < tolerance);
    CHECK(e.jacobian < tolerance);
    CHECK(e.hessian < tolerance);
}

}  // namespace modsynth::testing
