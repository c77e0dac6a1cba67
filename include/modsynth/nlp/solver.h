#pragma once
// Minimising a QuadraticProgram. The implementation adapts Ipopt; its headers
// stay out of this interface.
#include <string>
#include <vector>

#include <modsynth/nlp/quadratic_program.h>

namespace modsynth::nlp {

struct SolverOptions {
    double time_limit = 10.0;  ///< seconds of CPU time
    int max_iterations = 500;
    double tolerance = 1e-8;
    double constraint_tolerance = 1e-9;
    int print_level = 0;
};

struct SolverResult {
    enum class Status { Optimal, Acceptable, Infeasible, Failed };
    Status status = Status::Failed;
    std::vector<double> x;
    double objective = 0.0;
    int iterations = 0;
    std::string message;
    bool usable() const { return status == Status::Optimal || status == Status::Acceptable; }
};

SolverResult minimize(const QuadraticProgram& program, const SolverOptions& options);

}  // namespace modsynth::nlp
