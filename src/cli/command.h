#pragma once
// One subcommand of the modsynth CLI: its options live in `app`, `run`
// executes it and returns the exit code. Exceptions escape to main, the one
// place that maps them to exit codes.
#include <functional>
#include <string>

#include <CLI/CLI.hpp>

#include <modsynth/baseline/baseline.h>
#include <modsynth/io/output_check.h>
#include <modsynth/kinematics/robot.h>
#include <modsynth/output/exports.h>

#include "exit_code.h"

namespace modsynth::app {

struct Command {
    CLI::App* app = nullptr;
    std::function<int()> run;
};

Command add_validate(CLI::App& parent);
Command add_solve(CLI::App& parent);
Command add_batch(CLI::App& parent);
Command add_regress(CLI::App& parent);
Command add_export(CLI::App& parent);
Command add_certify(CLI::App& parent);
Command add_explain(CLI::App& parent);
Command add_serve(CLI::App& parent);
Command add_baseline(CLI::App& parent);
Command add_compare(CLI::App& parent);
Command add_import(CLI::App& parent);
Command add_export_svg(CLI::App& parent);

/// --report, --urdf, --csv, --build-sheet: shared by solve and export.
void add_export_options(CLI::App& sub, output::ExportPaths& paths);
/// The files those options name, with every file --parts may write, for
/// io::check_outputs.
std::vector<io::OutputFile> export_outputs(const output::ExportPaths& paths);

/// "2 joints, base (x, y), links a b m (total t m), elbow +1": the robot
/// line of solve's summary, and of baseline's.
std::string robot_summary(const kinematics::Robot& robot);

/// --points, --seed, --baseline-time-limit, --rrt-iterations, --goal-bias,
/// --no-shortcut: shared by baseline and compare.
void add_baseline_options(CLI::App& sub, baseline::BaselineOptions& options);

}  // namespace modsynth::app
