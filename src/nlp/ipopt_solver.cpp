// Ipopt behind modsynth::nlp::minimize: the adapter only delegates to the
// program (a QuadraticProgram with exact second derivatives, or a
// SmoothProgram whose second derivatives Ipopt approximates), so no other
// file sees Ipopt's headers.
#include <modsynth/nlp/solver.h>

#include <IpIpoptApplication.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <modsynth/nlp/block_ldl.h>
#include <modsynth/nlp/smooth_program.h>
#include <modsynth/nlp/warm_start.h>
#include <modsynth/text/format.h>
#include <modsynth/text/option_check.h>

namespace modsynth::nlp {
namespace {

using Ipopt::Index;
using Ipopt::Number;

// Only a QuadraticProgram gives Ipopt exact second derivatives.
template <class Program>
constexpr bool kExactHessian = std::is_same_v<Program, QuadraticProgram>;

template <class Program>
class Adapter : public Ipopt::TNLP {
public:
    Adapter(const Program& program, const SolverOptions& options, const WarmStart* warm)
        : p_(program),
          warm_(warm),
          watch_(options.watch),
          deadline_(options.deadline),
          min_variables_(options.watch.min_variables) {}

    SolverResult result;
    /// Why the watch or the wall clock stopped the solve ("" if neither did).
    std::string stopped;

    // Ipopt looks at its CPU-time limit only between iterations and a
    // diverging solve makes each iteration slower: the progress watch stops
    // it here instead, and the wall clock at the caller's deadline.
    bool intermediate_callback(Ipopt::AlgorithmMode mode, Index iter, Number, Number inf_pr,
                               Number inf_du, Number, Number, Number, Number, Number, Index,
                               const Ipopt::IpoptData*,
                               Ipopt::IpoptCalculatedQuantities*) override {
        if (deadline_.expired()) {
            stopped = "time limit";
            return false;
        }
        if (mode != Ipopt::RegularMode) return true;
        watch_.observe(iter, inf_pr, inf_du);
        // Signs of doom are sometimes wrong (Ipopt can recover from huge
        // duals): a small program, whose iterations stay cheap, finishes.
        if (p_.num_variables() < min_variables_) return true;
        stopped = watch_.doomed();
        return stopped.empty();
    }

    bool get_nlp_info(Index& n, Index& m, Index& nnz_jac, Index& nnz_hess,
                      IndexStyleEnum& style) override {
        n = p_.num_variables();
        m = p_.num_constraints();
        nnz_jac = static_cast<Index>(p_.jacobian_structure().size());
        if constexpr (kExactHessian<Program>)
            nnz_hess = static_cast<Index>(p_.hessian_structure().size());
        else
            nnz_hess = 0;
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

    bool get_starting_point(Index n, bool init_x, Number* x, bool init_z, Number* z_l, Number* z_u,
                            Index m, bool init_lambda, Number* lambda) override {
        if (warm_ == nullptr) {
            if (!init_x || init_z || init_lambda) return false;
            std::copy(p_.start().begin(), p_.start().begin() + n, x);
            return true;
        }
        if (init_x) std::copy(warm_->x.begin(), warm_->x.begin() + n, x);
        if (init_z) {
            std::copy(warm_->z_lower.begin(), warm_->z_lower.begin() + n, z_l);
            std::copy(warm_->z_upper.begin(), warm_->z_upper.begin() + n, z_u);
        }
        if (init_lambda) std::copy(warm_->lambda.begin(), warm_->lambda.begin() + m, lambda);
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
    bool eval_h(Index, const Number*, bool, Number sigma, Index, const Number* lambda, bool, Index,
                Index* rows, Index* cols, Number* values) override {
        if constexpr (!kExactHessian<Program>) {
            return false;  // never asked for: the Hessian is approximated
        } else if (values == nullptr) {
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

    void finalize_solution(Ipopt::SolverReturn status, Index n, const Number* x, const Number* z_l,
                           const Number* z_u, Index m, const Number*, const Number* lambda,
                           Number obj, const Ipopt::IpoptData*,
                           Ipopt::IpoptCalculatedQuantities*) override {
        result.x.assign(x, x + n);
        result.z_lower.assign(z_l, z_l + n);
        result.z_upper.assign(z_u, z_u + n);
        result.lambda.assign(lambda, lambda + m);
        result.objective = obj;
        switch (status) {
            case Ipopt::SUCCESS:
                result.status = SolverResult::Status::Optimal;
                break;
            case Ipopt::STOP_AT_ACCEPTABLE_POINT:
                result.status = SolverResult::Status::Acceptable;
                break;
            case Ipopt::LOCAL_INFEASIBILITY:
                result.status = SolverResult::Status::Infeasible;
                break;
            default:
                result.status = SolverResult::Status::Failed;
                break;
        }
        result.message = "Ipopt status " + std::to_string(static_cast<int>(status)) + " (" +
                         describe(status) + ")";
    }

private:
    // Ipopt's return codes in words, for messages.
    static const char* describe(Ipopt::SolverReturn status) {
        struct Named {
            Ipopt::SolverReturn status;
            const char* words;
        };
        static constexpr Named kNames[] = {
            {Ipopt::SUCCESS, "optimal"},
            {Ipopt::MAXITER_EXCEEDED, "iteration limit"},
            {Ipopt::CPUTIME_EXCEEDED, "time limit"},
            {Ipopt::STOP_AT_TINY_STEP, "tiny step"},
            {Ipopt::STOP_AT_ACCEPTABLE_POINT, "acceptable point"},
            {Ipopt::LOCAL_INFEASIBILITY, "locally infeasible"},
            {Ipopt::RESTORATION_FAILURE, "restoration failed"},
            {Ipopt::DIVERGING_ITERATES, "diverging iterates"},
            {Ipopt::ERROR_IN_STEP_COMPUTATION, "error in step computation"},
            {Ipopt::INVALID_NUMBER_DETECTED, "invalid number"},
        };
        for (const Named& n : kNames)
            if (n.status == status) return n.words;
        return "failed";
    }
    // Ipopt reads |bound| >= 1e19 as "no bound".
    static Number clip(double v) { return std::clamp(v, -1e19, 1e19); }
    const Program& p_;
    const WarmStart* warm_;
    ProgressWatch watch_;
    run::Deadline deadline_;
    int min_variables_;
};

// Which constraints keep the last iterate from being feasible, by label
// (each names its family and the task part it comes from), worst first.
struct Violated {
    int constraint = -1;
    double amount = 0.0;
};

// The constraints violated at x by more than `tolerance`, worst first (ties
// in constraint order, so the report is the same on every run).
template <class Program>
std::vector<Violated> violated_at(const Program& program, const std::vector<double>& x,
                                  double tolerance) {
    std::vector<double> g(static_cast<std::size_t>(program.num_constraints()));
    program.eval_constraints(x.data(), g.data());
    std::vector<Violated> out;
    for (int m = 0; m < program.num_constraints(); ++m) {
        const double v = g[static_cast<std::size_t>(m)];
        const double amount =
            std::max({0.0, program.constraint_lower(m) - v, v - program.constraint_upper(m)});
        if (amount > tolerance) out.push_back({m, amount});
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const Violated& a, const Violated& b) { return a.amount > b.amount; });
    return out;
}

template <class Program>
std::string worst_violations(const Program& program, const std::vector<double>& x,
                             const SolverOptions& options) {
    if (x.size() != static_cast<std::size_t>(program.num_variables())) return {};
    const auto violated = violated_at(program, x, options.constraint_tolerance);
    if (violated.empty()) return "; every constraint holds at the last iterate";
    std::string s = "; at the last iterate ";
    const std::size_t shown =
        std::min(violated.size(), static_cast<std::size_t>(options.reported_violations));
    for (std::size_t k = 0; k < shown; ++k) {
        s += k ? ", " : "";
        s += program.constraint_label(violated[k].constraint) +
             text::format(" is violated by %.3g", violated[k].amount);
    }
    if (violated.size() > shown) s += text::format(" (%zu violated in all)", violated.size());
    return s;
}

template <class Program>
SolverResult solve(const Program& program, const SolverOptions& options, const WarmStart* warm);

}  // namespace

bool SolverOptions::IsValid(std::string* error) const {
    return text::OptionCheck("SolverOptions", error)
        .greater("time_limit", time_limit, 0.0)
        .at_least("max_iterations", max_iterations, 0)
        .greater("tolerance", tolerance, 0.0)
        .greater("constraint_tolerance", constraint_tolerance, 0.0)
        .at_least("acceptable_tolerance", acceptable_tolerance, tolerance)
        .at_least("acceptable_constraint_tolerance", acceptable_constraint_tolerance,
                  constraint_tolerance)
        .at_least("acceptable_iterations", acceptable_iterations, 0)
        .greater("warm_push", warm_push, 0.0)
        .greater("warm_mu", warm_mu, 0.0)
        .within("print_level", print_level, 0, 12)
        .nested("watch", watch)
        .at_least("reported_violations", reported_violations, 0)
        .ok();
}

SolverResult minimize(const QuadraticProgram& program, const SolverOptions& options,
                      const WarmStart* warm) {
    return solve(program, options, warm);
}

SolverResult minimize(const SmoothProgram& program, const SolverOptions& options,
                      const WarmStart* warm) {
    return solve(program, options, warm);
}

namespace {

template <class Program>
SolverResult solve(const Program& program, const SolverOptions& options, const WarmStart* warm) {
    text::require_valid(options);
    if (warm && (warm->x.size() != static_cast<std::size_t>(program.num_variables()) ||
                 warm->z_lower.size() != warm->x.size() || warm->z_upper.size() != warm->x.size() ||
                 warm->lambda.size() != static_cast<std::size_t>(program.num_constraints())))
        throw std::invalid_argument("nlp::minimize: the warm start does not fit the program");
    Ipopt::SmartPtr<Adapter<Program>> nlp = new Adapter<Program>(program, options, warm);
    Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
    auto& o = *app->Options();
    o.SetStringValue("sb", "yes");
    o.SetIntegerValue("print_level", options.print_level);
    o.SetNumericValue("tol", options.tolerance);
    o.SetNumericValue("constr_viol_tol", options.constraint_tolerance);
    o.SetNumericValue("acceptable_tol", options.acceptable_tolerance);
    o.SetNumericValue("acceptable_constr_viol_tol", options.acceptable_constraint_tolerance);
    o.SetIntegerValue("acceptable_iter", options.acceptable_iterations);
    o.SetIntegerValue("max_iter", options.max_iterations);
    o.SetNumericValue("max_cpu_time", std::max(0.01, options.time_limit));
    o.SetStringValue("mu_strategy", "adaptive");
    o.SetStringValue("honor_original_bounds", "yes");
    if constexpr (!kExactHessian<Program>)
        o.SetStringValue("hessian_approximation", "limited-memory");
    if (warm) {
        // Close to a solution already: keep the point and its multipliers
        // nearly where they are, and start the barrier small.
        o.SetStringValue("warm_start_init_point", "yes");
        for (const char* push :
             {"warm_start_bound_push", "warm_start_bound_frac", "warm_start_slack_bound_push",
              "warm_start_slack_bound_frac", "warm_start_mult_bound_push"})
            o.SetNumericValue(push, options.warm_push);
        o.SetNumericValue("mu_init", options.warm_mu);
    }
    static const bool block_ldl_loaded = ldl::serves_as_ma27();
    const bool block_ldl =
        options.linear_solver == SolverOptions::LinearSolver::BlockLdl && block_ldl_loaded;
    if (block_ldl) {
        o.SetStringValue("linear_solver", "ma27");
        // MC19, the scaling Ipopt pairs with MA27, is not in the library.
        o.SetStringValue("linear_system_scaling", "none");
    }
    auto with_mumps = [&] {
        SolverOptions fallback = options;
        fallback.linear_solver = SolverOptions::LinearSolver::Mumps;
        return solve(program, fallback, warm);
    };
    // An empty name: never read ./ipopt.opt, which would override these silently.
    if (app->Initialize("") != Ipopt::Solve_Succeeded) {
        if (block_ldl) return with_mumps();
        SolverResult failed;
        failed.message = "Ipopt failed to initialise";
        return failed;
    }
    const Ipopt::ApplicationReturnStatus status = app->OptimizeTNLP(nlp);
    // An Ipopt built without the MA27 loader refuses the option.
    if (block_ldl && status == Ipopt::Invalid_Option) return with_mumps();
    SolverResult result = nlp->result;
    if (!nlp->stopped.empty()) {
        result.status = SolverResult::Status::Failed;
        result.message = "stopped early (" + nlp->stopped + ")";
    }
    if (result.x.empty())
        result.message = "Ipopt returned " + std::to_string(static_cast<int>(status));
    if (!result.usable()) result.message += worst_violations(program, result.x, options);
    if (auto stats = app->Statistics(); Ipopt::IsValid(stats))
        result.iterations = stats->IterationCount();
    return result;
}

}  // namespace

}  // namespace modsynth::nlp
