#pragma once
// A nonlinear program given by its values and first derivatives alone:
// minimise f(x) subject to lower <= g(x) <= upper and bounds on x, with a
// sparse Jacobian of g. Where the constraints are not polynomials of low
// degree (the spatial refinement's come from the closed-form inverse
// kinematics and exact distances), second derivatives are left to the
// solver's limited-memory quasi-Newton approximation. Like
// QuadraticProgram, the model knows nothing of the solver.
#include <string>
#include <vector>

namespace modsynth::nlp {

class SmoothProgram {
public:
    struct Entry {
        int row, col;
    };

    virtual ~SmoothProgram() = default;

    virtual int num_variables() const = 0;
    virtual int num_constraints() const = 0;
    virtual const std::vector<double>& variable_lower() const = 0;
    virtual const std::vector<double>& variable_upper() const = 0;
    virtual const std::vector<double>& start() const = 0;
    virtual double constraint_lower(int m) const = 0;
    virtual double constraint_upper(int m) const = 0;
    /// Names the constraint's family and the task parts it comes from, for
    /// messages about the constraints a failed solve left violated.
    virtual const std::string& constraint_label(int m) const = 0;
    /// Fixed once the program is built.
    virtual const std::vector<Entry>& jacobian_structure() const = 0;

    virtual double eval_objective(const double* x) const = 0;
    virtual void eval_gradient(const double* x, double* grad) const = 0;
    virtual void eval_constraints(const double* x, double* g) const = 0;
    /// In jacobian_structure() order.
    virtual void eval_jacobian(const double* x, double* values) const = 0;
};

}  // namespace modsynth::nlp
