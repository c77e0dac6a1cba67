#include "task_file.h"

#include <cstdio>

#include <modsynth/io/check_timeout.h>

namespace modsynth::app {

void add_strict_option(CLI::App& sub, bool& strict) {
    sub.add_flag("--strict", strict,
                 "Refuse a task with a key the format does not define (a warning otherwise)");
}

io::TaskDocument read_task_file(const std::string& path, bool strict,
                                const run::Deadline& deadline) {
    io::TaskWarnings warnings;
    // Printed before an error too: a task in millimetres may break a cap.
    const auto print = [&] {
        for (const task::InputError& w : warnings.unknown_keys)
            std::fprintf(stderr, "warning: %s (the task is read without it)\n", w.what());
        for (const task::InputError& w : warnings.units)
            std::fprintf(stderr, "warning: %s\n", w.what());
    };
    io::TaskDocument doc;
    try {
        doc = io::load_task_document(path, warnings, deadline);
    } catch (const task::InputError&) {
        print();
        throw;
    } catch (const io::CheckTimeout&) {
        print();
        throw;
    }
    if (strict && !warnings.unknown_keys.empty()) {
        const task::InputError& w = warnings.unknown_keys.front();
        throw task::InputError(w.part(), w.problem() + " (refused with --strict)").in_file(path);
    }
    print();
    return doc;
}

}  // namespace modsynth::app
