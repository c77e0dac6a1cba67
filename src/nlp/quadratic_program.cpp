#include <modsynth/nlp/quadratic_program.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <map>

namespace modsynth::nlp {

double Quadratic::value(const double* x) const {
    double v = constant;
    for (const auto& [i, a] : linear) v += a * x[i];
    for (const auto& t : quadratic) v += t.w * x[t.i] * x[t.j];
    return v;
}

void Quadratic::add_gradient(const double* x, double scale, double* grad) const {
    for (const auto& [i, a] : linear) grad[i] += scale * a;
    for (const auto& t : quadratic) {
        grad[t.i] += scale * t.w * x[t.j];
        grad[t.j] += scale * t.w * x[t.i];
    }
}

int QuadraticProgram::add_variable(double lower, double upper, double start, std::string name,
                                   Key key) {
    assert(lower <= upper);
    lower_.push_back(lower);
    upper_.push_back(upper);
    start_.push_back(std::clamp(start, lower, upper));
    names_.push_back(std::move(name));
    variable_keys_.push_back(key);
    return num_variables() - 1;
}

int QuadraticProgram::add_constraint(Quadratic g, double lower, double upper, std::string label,
                                     Key key) {
    constraints_.push_back(std::move(g));
    c_lower_.push_back(lower);
    c_upper_.push_back(upper);
    labels_.push_back(std::move(label));
    constraint_keys_.push_back(key);
    return num_constraints() - 1;
}

void QuadraticProgram::finalize() {
    jac_.clear();
    hess_.clear();
    jac_slot_linear_.assign(constraints_.size(), {});
    jac_slot_quadratic_.assign(constraints_.size(), {});
    hess_slot_.assign(constraints_.size(), {});
    std::map<std::pair<int, int>, int> hess_index;
    auto hess_slot = [&](int i, int j) {
        const std::pair<int, int> key{std::max(i, j), std::min(i, j)};
        auto [it, inserted] = hess_index.emplace(key, static_cast<int>(hess_.size()));
        if (inserted) hess_.push_back({key.first, key.second});
        return it->second;
    };
    for (std::size_t m = 0; m < constraints_.size(); ++m) {
        const Quadratic& g = constraints_[m];
        std::map<int, int> col_slot;
        auto slot = [&](int col) {
            auto [it, inserted] = col_slot.emplace(col, static_cast<int>(jac_.size()));
            if (inserted) jac_.push_back({static_cast<int>(m), col});
            return it->second;
        };
        for (const auto& [i, a] : g.linear) {
            assert(i >= 0 && i < num_variables());
            jac_slot_linear_[m].push_back(slot(i));
        }
        for (const auto& t : g.quadratic) {
            assert(t.i >= 0 && t.i < num_variables() && t.j >= 0 && t.j < num_variables());
            jac_slot_quadratic_[m].push_back({slot(t.i), slot(t.j)});
            hess_slot_[m].push_back(hess_slot(t.i, t.j));
        }
    }
    hess_slot_objective_.clear();
    for (const auto& t : objective_.quadratic) hess_slot_objective_.push_back(hess_slot(t.i, t.j));
}

void QuadraticProgram::eval_gradient(const double* x, double* grad) const {
    std::fill(grad, grad + num_variables(), 0.0);
    objective_.add_gradient(x, 1.0, grad);
}

void QuadraticProgram::eval_constraints(const double* x, double* g) const {
    for (std::size_t m = 0; m < constraints_.size(); ++m) g[m] = constraints_[m].value(x);
}

void QuadraticProgram::eval_jacobian(const double* x, double* values) const {
    std::fill(values, values + jac_.size(), 0.0);
    for (std::size_t m = 0; m < constraints_.size(); ++m) {
        const Quadratic& g = constraints_[m];
        for (std::size_t k = 0; k < g.linear.size(); ++k)
            values[jac_slot_linear_[m][k]] += g.linear[k].second;
        for (std::size_t k = 0; k < g.quadratic.size(); ++k) {
            const auto& t = g.quadratic[k];
            values[jac_slot_quadratic_[m][k].first] += t.w * x[t.j];
            values[jac_slot_quadratic_[m][k].second] += t.w * x[t.i];
        }
    }
}

namespace {
// Second derivative contribution of w x_i x_j to its (lower-triangle) slot.
double hessian_weight(const Quadratic::Term& t) { return t.i == t.j ? 2.0 * t.w : t.w; }
}  // namespace

void QuadraticProgram::eval_hessian(double sigma, const double* lambda, double* values) const {
    std::fill(values, values + hess_.size(), 0.0);
    for (std::size_t k = 0; k < objective_.quadratic.size(); ++k)
        values[hess_slot_objective_[k]] += sigma * hessian_weight(objective_.quadratic[k]);
    for (std::size_t m = 0; m < constraints_.size(); ++m) {
        const Quadratic& g = constraints_[m];
        for (std::size_t k = 0; k < g.quadratic.size(); ++k)
            values[hess_slot_[m][k]] += lambda[m] * hessian_weight(g.quadratic[k]);
    }
}

double QuadraticProgram::constraint_violation(int m, const double* x) const {
    const double v = constraints_[m].value(x);
    return std::max({0.0, c_lower_[m] - v, v - c_upper_[m]});
}

double QuadraticProgram::infeasibility(const double* x) const {
    double worst = 0.0;
    for (int i = 0; i < num_variables(); ++i)
        worst = std::max({worst, lower_[i] - x[i], x[i] - upper_[i]});
    for (int m = 0; m < num_constraints(); ++m) worst = std::max(worst, constraint_violation(m, x));
    return worst;
}

std::vector<QuadraticProgram::Violated> QuadraticProgram::violated(const double* x,
                                                                   double tolerance) const {
    std::vector<Violated> out;
    for (int m = 0; m < num_constraints(); ++m) {
        const double amount = constraint_violation(m, x);
        if (amount > tolerance) out.push_back({m, amount});
    }
    // Ties keep constraint order, so the report is the same on every run.
    std::stable_sort(out.begin(), out.end(),
                     [](const Violated& a, const Violated& b) { return a.amount > b.amount; });
    return out;
}

}  // namespace modsynth::nlp
