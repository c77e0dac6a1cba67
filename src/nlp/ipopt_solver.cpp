// Ipopt behind modsynth::nlp::minimize: the adapter only delegates to the
// QuadraticProgram, so no other file sees Ipopt's headers.
#include <modsynth/nlp/solver.h>

#include <IpIpoptApplication.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>

#include <algorithm>
#include <string>

namespace modsynth::nlp {
namespace {

using Ipopt::Index;
using Ipopt::Number;

class Adapter : public Ipopt::TNLP {
public:
    explicit Adapter(const QuadraticProgram& program) : p_(program) {}

    SolverResult result;

    bool get_nlp_info(Index& n, Index& m, Index& nnz_jac, Index& nnz_hess,
                      IndexStyleEnum& style) override {
        n = p_.num_variables();
        m = p_.num_constraints();
        nnz_jac = static_cast<Index>(p_.jacobian_structure().size());
        nnz_hess = static_cast<Index>(p_.hessian_structure().size());
        style = C_STYLE;
        return true;
    }

    bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index m, Number* g_l,
                         Number* g_u) override {
        for (Index i = 0; i < n; ++i) {
            x_l[i] = clip(p_.variable_lower()[i]);
            x_u[i] = clip(p_.variable_upper()[i]);
        }
        for (Index k = 0; k < m; ++k) {
            g_l[k] = clip(p_.constraint_lower(k));
            g_u[k] = clip(p_.constraint_upper(k));
        }
        return true;
    }

    bool get_starting_point(Index n, bool init_x, Number* x, bool init_z, Number*, Number*,
                            Index, bool init_lambda, Number*) override {
        if (!init_x || init_z || init_lambda) return false;
        std::copy(p_.start().begin(), p_.start().begin() + n, x);
        return true;
    }

    bool eval_f(Index, const Number* x, bool, Number& f) override {
        f = p_.eval_objective(x);
        return true;
    }
    bool eval_grad_f(Index, const Number* x, bool, Number* grad) override {
        p_.eval_gradient(x, grad);
        return true;
    }
    bool eval_g(Index, const Number* x, bool, Index, Number* g) override {
        p_.eval_constraints(x, g);
        return true;
    }
    bool eval_jac_g(Index, const Number* x, bool, Index, Index, Index* rows, Index* cols,
                    Number* values) override {
        if (values == nullptr) {
            const auto& s = p_.jacobian_structure();
            for (std::size_t k = 0; k < s.size(); ++k) {
                rows[k] = s[k].row;
                cols[k] = s[k].col;
            }
        } else {
            p_.eval_jacobian(x, values);
        }
        return true;
    }
    bool eval_h(Index, const Number*, bool, Number sigma, Index, const Number* lambda, bool,
                Index, Index* rows, Index* cols, Number* values) override {
        if (values == nullptr) {
            const auto& s = p_.hessian_structure();
            for (std::size_t k = 0; k < s.size(); ++k) {
                rows[k] = s[k].row;
                cols[k] = s[k].col;
            }
        } else {
            p_.eval_hessian(sigma, lambda, values);
        }
        return true;
    }

    void finalize_solution(Ipopt::SolverReturn status, Index n, const Number* x, const Number*,
                           const Number*, Index, const Number*, const Number*, Number obj,
                           const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
        result.x.assign(x, x + n);
        result.objective = obj;
        switch (status) {
            case Ipopt::SUCCESS: result.status = SolverResult::Status::Optimal; break;
            case Ipopt::STOP_AT_ACCEPTABLE_POINT:
                result.status = SolverResult::Status::Acceptable;
                break;
            case Ipopt::LOCAL_INFEASIBILITY:
                result.status = SolverResult::Status::Infeasible;
                break;
            default: result.status = SolverResult::Status::Failed; break;
        }
        result.message = "Ipopt status " + std::to_string(static_cast<int>(status));
    }

private:
    // Ipopt reads |bound| >= 1e19 as "no bound".
    static Number clip(double v) { return std::clamp(v, -1e19, 1e19); }
    const QuadraticProgram& p_;
};

}  // namespace

SolverResult minimize(const QuadraticProgram& program, const SolverOptions& options) {
    Ipopt::SmartPtr<Adapter> nlp = new Adapter(program);
    Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
    auto& o = *app->Options();
    o.SetStringValue("sb", "yes");
    o.SetIntegerValue("print_level", options.print_level);
    o.SetNumericValue("tol", options.tolerance);
    o.SetNumericValue("constr_viol_tol", options.constraint_tolerance);
    o.SetNumericValue("acceptable_tol", 1e-5);
    o.SetNumericValue("acceptable_constr_viol_tol", 1e-7);
    o.SetIntegerValue("max_iter", options.max_iterations);
    o.SetNumericValue("max_cpu_time", std::max(0.01, options.time_limit));
    o.SetStringValue("mu_strategy", "adaptive");
    o.SetStringValue("honor_original_bounds", "yes");
    // An empty name: never read ./ipopt.opt, which would override these silently.
    if (app->Initialize("") != Ipopt::Solve_Succeeded) {
        SolverResult failed;
        failed.message = "Ipopt failed to initialise";
        return failed;
    }
    const Ipopt::ApplicationReturnStatus status = app->OptimizeTNLP(nlp);
    SolverResult result = nlp->result;
    if (result.x.empty()) result.message = "Ipopt returned " + std::to_string(static_cast<int>(status));
    if (auto stats = app->Statistics(); Ipopt::IsValid(stats))
        result.iterations = stats->IterationCount();
    return result;
}

}  // namespace modsynth::nlp
