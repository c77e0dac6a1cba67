// The modsynth command line. The only place that maps outcomes and errors to
// exit codes: 0 solved (or valid), 1 internal error, 2 invalid input or
// usage, 3 infeasible, 4 unknown.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>

#include <modsynth/output/solution_io.h>
#include <modsynth/synth/synthesizer.h>
#include <modsynth/task/task_io.h>

namespace {

enum Exit { kOk = 0, kInternal = 1, kInvalid = 2, kInfeasible = 3, kUnknown = 4 };

int validate(const std::string& path) {
    const modsynth::task::Task task = modsynth::task::load_task(path);
    std::printf("%s: valid task '%s': %zu primitives, %zu obstacles, %zu base regions\n", path.c_str(),
                task.name.c_str(), task.trajectory.size(), task.obstacles.size(), task.base_regions.size());
    return kOk;
}

struct SolveArgs {
    std::string task, output;
    double time_limit = 60.0;
    unsigned seed = 0;
    double ee_speed = 0.05, joint_speed = 1.0;
    bool quiet = false;
};

int solve(const SolveArgs& a) {
    using namespace modsynth;
    const task::Task task = task::load_task(a.task);
    synth::SynthesisOptions options;
    options.time_limit = a.time_limit;
    options.seed = a.seed;
    options.motion.ee_speed = a.ee_speed;
    options.motion.joint_speed = a.joint_speed;
    if (!a.quiet) options.progress = [](const std::string& line) { std::cerr << line << '\n'; };
    synth::SynthesisStats stats;
    const auto t0 = std::chrono::steady_clock::now();
    const synth::Solution solution = synth::synthesize(task, options, &stats);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    output::write_solution(solution, a.output);

    std::printf("%s: %s in %.3f s (front stage %.3f s, refinement %.3f s, verification %.3f s)\n",
                task.name.c_str(), synth::to_string(solution.status), seconds, stats.front_seconds,
                stats.refine_seconds, stats.verify_seconds);
    if (solution.status == synth::Status::Solved) {
        const auto& r = solution.robot;
        std::printf("  robot: %d joints, base (%.4f, %.4f), links", r.dof(), r.base.x(), r.base.y());
        for (double l : r.link_lengths) std::printf(" %.4f", l);
        std::printf(" m (total %.4f m), elbow %+d\n", r.total_length(), r.elbow);
        const auto& c = solution.certificate;
        std::printf("  certified over the whole motion: clearance margin %.4f m, self-collision margin "
                    "%.4f m, EE deviation <= %.2e m\n",
                    c.min_clearance, c.min_self_clearance, c.max_deviation);
        std::printf("  control: %zu samples over %.2f s -> %s\n", solution.samples.size(),
                    solution.samples.back().t, a.output.c_str());
        return kOk;
    }
    std::printf("  %s\n", solution.explanation.message.c_str());
    if (!solution.explanation.core.empty()) {
        std::printf("  core:");
        for (const auto& c : solution.explanation.core) std::printf(" %s", c.c_str());
        std::printf("\n");
    }
    return solution.status == synth::Status::Infeasible ? kInfeasible : kUnknown;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"modsynth: synthesise a modular planar manipulator and its control for a task"};
    app.set_version_flag("--version", std::string("modsynth ") + MODSYNTH_VERSION);
    app.require_subcommand(1);

    std::string validate_path;
    auto* val = app.add_subcommand("validate", "Check a task file (exit 0 valid, 2 invalid)");
    val->add_option("TASK", validate_path, "modsynth-task/1 JSON file")->required();

    SolveArgs sa;
    auto* sol = app.add_subcommand("solve", "Synthesise a robot and its control for a task");
    sol->add_option("TASK", sa.task, "modsynth-task/1 JSON file")->required();
    sol->add_option("-o,--output", sa.output, "where to write the modsynth-solution/1 JSON")->required();
    sol->add_option("--time-limit", sa.time_limit, "seconds for the whole run (default 60)")
        ->check(CLI::PositiveNumber);
    sol->add_option("--seed", sa.seed, "varies initial guesses; same seed, same output (default 0)");
    sol->add_option("--ee-speed", sa.ee_speed, "end-effector speed along the path, m/s (default 0.05)")
        ->check(CLI::PositiveNumber);
    sol->add_option("--joint-speed", sa.joint_speed, "joint speed limit, rad/s (default 1)")
        ->check(CLI::PositiveNumber);
    sol->add_flag("-q,--quiet", sa.quiet, "no progress lines on stderr");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? kOk : kInvalid;
    }
    try {
        if (*val) return validate(validate_path);
        if (*sol) return solve(sa);
    } catch (const modsynth::task::InputError& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return kInvalid;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "internal error: %s\n", e.what());
        return kInternal;
    }
    return kInternal;
}
