#include "part_literals.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>

#include <modsynth/run/stopwatch.h>

namespace modsynth::smt {

z3::expr PartLiterals::literal(const task::TaskPart& part) {
    auto it = literal_of_.find(part);
    if (it != literal_of_.end()) return it->second;
    z3::expr l = ctx_.bool_const(task::to_string(part).c_str());
    literal_of_.emplace(part, l);
    parts_.push_back(part);
    return l;
}

z3::expr PartLiterals::guarded(std::initializer_list<task::TaskPart> parts, const z3::expr& e) {
    z3::expr_vector guards(ctx_);
    for (const auto& part : parts) guards.push_back(literal(part));
    return z3::implies(z3::mk_and(guards), e);
}

z3::expr_vector PartLiterals::all() const {
    z3::expr_vector a(ctx_);
    for (const auto& part : parts_) a.push_back(literal_of_.at(part));
    return a;
}

z3::expr_vector PartLiterals::of(const std::vector<task::TaskPart>& parts) const {
    z3::expr_vector a(ctx_);
    for (const auto& part : parts) {
        auto it = literal_of_.find(part);
        if (it != literal_of_.end()) a.push_back(it->second);
    }
    return a;
}

std::vector<task::TaskPart> PartLiterals::parts_of(const std::vector<z3::expr>& literals) const {
    std::vector<task::TaskPart> out;
    for (const auto& part : parts_) {
        const z3::expr& l = literal_of_.at(part);
        if (std::any_of(literals.begin(), literals.end(),
                        [&](const z3::expr& e) { return z3::eq(e, l); }))
            out.push_back(part);
    }
    return out;
}

std::string PartLiterals::script(z3::solver& solver) const {
    std::string s = solver.to_smt2();
    const auto pos = s.rfind("(check-sat)");
    if (pos != std::string::npos) s.erase(pos);
    s += "(check-sat-assuming (";
    for (std::size_t i = 0; i < parts_.size(); ++i)
        s += (i ? " |" : "|") + task::to_string(parts_[i]) + "|";
    return s + "))\n";
}

void set_timeout(z3::context& ctx, z3::solver& solver, double seconds,
                 const run::Deadline& deadline) {
    z3::params p(ctx);
    p.set("unsat_core", true);
    const double ms = std::min({seconds, deadline.remaining(), 1e6}) * 1000.0;
    p.set("timeout", static_cast<unsigned>(std::max(1.0, ms)));
    solver.set(p);
}

z3::check_result check(z3::context& ctx, z3::solver& solver, const z3::expr_vector& assumptions,
                       const run::Deadline& deadline) {
    if (!deadline.can_be_cancelled()) return solver.check(assumptions);
    // Z3's timeout cannot see a cancel token: a watcher interrupts the
    // context when the run is cancelled during the check.
    std::atomic<bool> done{false};
    std::thread watcher([&] {
        while (!done.load(std::memory_order_relaxed)) {
            if (deadline.cancelled()) {
                ctx.interrupt();
                return;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
    });
    z3::check_result r = z3::unknown;
    try {
        r = solver.check(assumptions);
    } catch (...) {
        done = true;
        watcher.join();
        throw;
    }
    done = true;
    watcher.join();
    return r;
}

std::vector<z3::expr> minimal_core(z3::context& ctx, z3::solver& solver,
                                   const z3::expr_vector& assumptions, const CoreBudget& budget,
                                   const run::Deadline& deadline) {
    if (deadline.expired()) return {};
    set_timeout(ctx, solver, budget.seconds, deadline);
    // Other checks may have run since the conflict was found: it is
    // re-established, so that the core below is this one's.
    const run::Stopwatch conflict;
    if (check(ctx, solver, assumptions, deadline) != z3::unsat) return {};
    // A trial without a needed literal is satisfiable, and nlsat can take
    // its whole timeout to find the model (10 s on a 640-primitive path,
    // where the conflict itself takes 0.3 s): trials get a few times what
    // the conflict took.
    const double trial_limit = std::min(
        budget.seconds, std::max(budget.trial_seconds, budget.trial_factor * conflict.seconds()));
    const z3::expr_vector core = solver.unsat_core();
    std::vector<z3::expr> kept;
    for (unsigned i = 0; i < core.size(); ++i) kept.push_back(core[i]);
    for (std::size_t i = 0; i < kept.size() && !deadline.expired();) {
        set_timeout(ctx, solver, trial_limit, deadline);
        z3::expr_vector trial(ctx);
        for (std::size_t k = 0; k < kept.size(); ++k)
            if (k != i) trial.push_back(kept[k]);
        if (check(ctx, solver, trial, deadline) == z3::unsat) {
            // The trial's own core may be smaller still: only that is kept.
            const z3::expr_vector smaller = solver.unsat_core();
            std::vector<z3::expr> next;
            for (std::size_t k = 0; k < kept.size(); ++k) {
                if (k == i) continue;
                for (unsigned c = 0; c < smaller.size(); ++c)
                    if (z3::eq(kept[k], smaller[c])) next.push_back(kept[k]);
            }
            kept = std::move(next);
            i = std::min(i, kept.size());
        } else {
            ++i;
        }
    }
    return kept;
}

}  // namespace modsynth::smt
