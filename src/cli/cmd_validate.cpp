#include <cstdio>
#include <memory>
#include <string>
#include <variant>

#include <modsynth/hardware/task_catalog.h>
#include <modsynth/io/check_timeout.h>
#include <modsynth/io/task_document.h>
#include <modsynth/text/printable.h>

#include "command.h"
#include "number_checks.h"
#include "task_file.h"

namespace modsynth::app {

Command add_validate(CLI::App& parent) {
    auto path = std::make_shared<std::string>();
    auto time_limit = std::make_shared<double>(60.0);
    auto strict = std::make_shared<bool>(false);
    CLI::App* sub = parent.add_subcommand(
        "validate", "Check a task file (exit 0 valid, 2 invalid, 4 not checked in time)");
    sub->add_option("TASK", *path, "modsynth-task/1 JSON file")->required();
    sub->add_option("--time-limit", *time_limit,
                    "seconds for the checks: a long path among many obstacles takes long to "
                    "check (default 60)")
        ->check(seconds());
    add_strict_option(*sub, *strict);
    return {sub, [path, time_limit, strict] {
                io::TaskDocument doc;
                try {
                    doc = read_task_file(*path, *strict, run::Deadline::in(*time_limit));
                } catch (const io::CheckTimeout& e) {
                    std::printf("%s: not checked within the time limit (%g s): %s\n",
                                text::printable(*path, 200).c_str(), *time_limit, e.what());
                    return int{kUnknown};
                }
                // robot.modules must name modules of the catalog.
                if (const auto* t = std::get_if<task::Task>(&doc)) {
                    if (!t->robot.modules.empty()) hardware::catalog_for(*t);
                } else if (const auto& s = std::get<task::SpatialTask>(doc);
                           !s.robot.modules.empty()) {
                    task::Task names;
                    names.robot.modules = s.robot.modules;
                    hardware::catalog_for(names);
                }
                std::visit(
                    [&](const auto& t) {
                        const bool spatial =
                            std::is_same_v<std::decay_t<decltype(t)>, task::SpatialTask>;
                        std::printf(
                            "%s: valid %stask '%s': %zu primitives, %zu obstacles, %zu "
                            "base regions\n",
                            text::printable(*path, 200).c_str(), spatial ? "spatial " : "",
                            text::printable(t.name, 80).c_str(), t.trajectory.size(),
                            t.obstacles.size(), t.base_regions.size());
                    },
                    doc);
                return int{kOk};
            }};
}

}  // namespace modsynth::app
