#include <cstdio>
#include <memory>
#include <string>
#include <variant>

#include <modsynth/hardware/task_catalog.h>
#include <modsynth/io/task_document.h>
#include <modsynth/text/printable.h>

#include "command.h"
#include "task_file.h"

namespace modsynth::app {

Command add_validate(CLI::App& parent) {
    auto path = std::make_shared<std::string>();
    auto strict = std::make_shared<bool>(false);
    CLI::App* sub =
        parent.add_subcommand("validate", "Check a task file (exit 0 valid, 2 invalid)");
    sub->add_option("TASK", *path, "modsynth-task/1 JSON file")->required();
    add_strict_option(*sub, *strict);
    return {sub, [path, strict] {
                const io::TaskDocument doc = read_task_file(*path, *strict);
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
                            path->c_str(), spatial ? "spatial " : "",
                            text::printable(t.name, 80).c_str(), t.trajectory.size(),
                            t.obstacles.size(), t.base_regions.size());
                    },
                    doc);
                return int{kOk};
            }};
}

}  // namespace modsynth::app
