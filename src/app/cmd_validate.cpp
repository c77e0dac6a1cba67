#include <cstdio>
#include <memory>
#include <string>

#include <modsynth/hardware/task_catalog.h>
#include <modsynth/io/task_io.h>

#include <modsynth/text/printable.h>

#include "command.h"

namespace modsynth::app {

Command add_validate(CLI::App& parent) {
    auto path = std::make_shared<std::string>();
    CLI::App* sub =
        parent.add_subcommand("validate", "Check a task file (exit 0 valid, 2 invalid)");
    sub->add_option("TASK", *path, "modsynth-task/1 JSON file")->required();
    return {sub, [path] {
                const task::Task t = io::load_task(*path);
                // robot.modules must name modules of the catalog.
                if (!t.robot.modules.empty()) hardware::catalog_for(t);
                std::printf(
                    "%s: valid task '%s': %zu primitives, %zu obstacles, %zu base regions\n",
                    path->c_str(), text::printable(t.name, 80).c_str(), t.trajectory.size(),
                    t.obstacles.size(), t.base_regions.size());
                return int{kOk};
            }};
}

}  // namespace modsynth::app
