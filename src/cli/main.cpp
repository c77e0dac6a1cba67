// The modsynth command line. Exit codes: 0 solved (or valid, or certified),
// 1 internal error, 2 invalid input or usage, 3 infeasible, 4 unknown,
// 5 not certified (certify).
#include <cstdio>
#include <string>
#include <vector>

#include <modsynth/hardware/catalog.h>
#include <modsynth/io/atomic_file.h>
#include <modsynth/task/input_error.h>

#include "command.h"

int main(int argc, char** argv) {
    using namespace modsynth::app;
    CLI::App app{"modsynth: synthesise a modular planar manipulator and its control for a task"};
    app.set_version_flag("--version", std::string("modsynth ") + MODSYNTH_VERSION);
    app.require_subcommand(1);
    const std::vector<Command> commands = {
        add_validate(app), add_solve(app),   add_export(app),     add_batch(app),
        add_regress(app),  add_explain(app), add_serve(app),      add_baseline(app),
        add_compare(app),  add_import(app),  add_export_svg(app), add_certify(app)};
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? kOk : kInvalid;
    }
    try {
        for (const Command& c : commands)
            if (c.app->parsed()) return c.run();
    } catch (const modsynth::task::InputError& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return kInvalid;
    } catch (const modsynth::hardware::CatalogError& e) {
        // The module catalog is an input like the task: a file in it that
        // cannot be read is refused by name.
        std::fprintf(stderr, "error: %s\n", e.what());
        return kInvalid;
    } catch (const modsynth::io::WriteError& e) {
        // An output not written: exit 1 as README says, but not a defect.
        std::fprintf(stderr, "error: %s\n", e.what());
        return kInternal;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "internal error: %s\n", e.what());
        return kInternal;
    }
    return kInternal;
}
