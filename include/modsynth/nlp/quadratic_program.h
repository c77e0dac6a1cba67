#pragma once
// A smooth nonlinear program whose objective and constraints are quadratic
// polynomials. Every constraint of modsynth's refinement (link consistency,
// elbow side, separating lines) is bilinear in the base, the link lengths,
// the joint positions and the separating normals, so this one shape gives
// exact first and second derivatives for all of them. The model knows
// nothing of the solver that minimises it.
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <modsynth/nlp/key.h>

namespace modsynth::nlp {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// c + sum a_i x_i + sum w_ij x_i x_j.
struct Quadratic {
    double constant = 0.0;
    std::vector<std::pair<int, double>> linear;
    struct Term {
        int i, j;
        double w;
    };
    std::vector<Term> quadratic;

    Quadratic& add(double c) {
        constant += c;
        return *this;
    }
    Quadratic& add(int i, double a) {
        linear.push_back({i, a});
        return *this;
    }
    Quadratic& add(int i, int j, double w) {
        quadratic.push_back({i, j, w});
        return *this;
    }

    double value(const double* x) const;
    /// Adds scale * gradient into grad (dense).
    void add_gradient(const double* x, double scale, double* grad) const;
};

class QuadraticProgram {
public:
    /// `name` and `label` are for people; `key` is what a warm start
    /// matches by (warm_start.h; unkeyed ones start afresh).
    int add_variable(double lower, double upper, double start, std::string name, Key key = {});
    int add_constraint(Quadratic g, double lower, double upper, std::string label, Key key = {});
    void set_objective(Quadratic f) { objective_ = std::move(f); }

    int num_variables() const { return static_cast<int>(lower_.size()); }
    int num_constraints() const { return static_cast<int>(constraints_.size()); }
    const std::vector<double>& variable_lower() const { return lower_; }
    const std::vector<double>& variable_upper() const { return upper_; }
    const std::vector<double>& start() const { return start_; }
    void set_start(int i, double v) { start_[i] = v; }
    const std::string& variable_name(int i) const { return names_[i]; }
    const std::string& constraint_label(int m) const { return labels_[m]; }
    const Key& variable_key(int i) const { return variable_keys_[i]; }
    const Key& constraint_key(int m) const { return constraint_keys_[m]; }
    double constraint_lower(int m) const { return c_lower_[m]; }
    double constraint_upper(int m) const { return c_upper_[m]; }
    const Quadratic& constraint(int m) const { return constraints_[m]; }
    const Quadratic& objective() const { return objective_; }

    /// Sparse structure, fixed once the model is built (call finalize()).
    void finalize();
    struct Entry {
        int row, col;
    };
    const std::vector<Entry>& jacobian_structure() const { return jac_; }
    /// Lower triangle (row >= col) of the Hessian of the Lagrangian.
    const std::vector<Entry>& hessian_structure() const { return hess_; }

    double eval_objective(const double* x) const { return objective_.value(x); }
    void eval_gradient(const double* x, double* grad) const;
    void eval_constraints(const double* x, double* g) const;
    void eval_jacobian(const double* x, double* values) const;
    /// sigma * Hessian(f) + sum lambda_m Hessian(g_m), in hessian_structure() order.
    void eval_hessian(double sigma, const double* lambda, double* values) const;

    /// Largest violation of constraints and bounds at x.
    double infeasibility(const double* x) const;

    struct Violated {
        int constraint = -1;
        double amount = 0.0;  ///< how far outside its bounds, in its own units
    };
    /// The constraints violated at x by more than `tolerance`, worst first.
    std::vector<Violated> violated(const double* x, double tolerance) const;

private:
    double constraint_violation(int m, const double* x) const;

    std::vector<double> lower_, upper_, start_;
    std::vector<std::string> names_;
    std::vector<Quadratic> constraints_;
    std::vector<double> c_lower_, c_upper_;
    std::vector<std::string> labels_;
    std::vector<Key> variable_keys_, constraint_keys_;
    Quadratic objective_;
    std::vector<Entry> jac_, hess_;
    // Per constraint, where each of its linear and quadratic terms lands.
    std::vector<std::vector<int>> jac_slot_linear_;
    std::vector<std::vector<std::pair<int, int>>> jac_slot_quadratic_;
    std::vector<std::vector<int>> hess_slot_;
    std::vector<int> hess_slot_objective_;
};

}  // namespace modsynth::nlp
