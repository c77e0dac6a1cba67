// `solve --events`: a line the disk will not take is reported, not lost.
#include <catch2/catch.hpp>

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include <modsynth/io/atomic_file.h>
#include <modsynth/run/progress.h>

#include "solve_guard.h"

namespace fs = std::filesystem;

TEST_CASE("events the disk does not take are reported when the run ends", "[cli][events]") {
    const fs::path dir = fs::temp_directory_path() / "modsynth-events-test";
    fs::create_directories(dir);
    const std::string path = (dir / "events.jsonl").string();
    const pid_t pid = fork();
    if (pid == 0) {
        // A file size limit stands for a full disk: the first lines fit,
        // a later one does not.
        signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{2048, 2048};
        setrlimit(RLIMIT_FSIZE, &limit);
        int code = 1;
        {
            modsynth::app::SolveGuard guard("t", 60.0, 0.0, [](const auto&) {});
            modsynth::app::SolveProgress progress(path, true);
            const auto sink = progress.sink(guard);
            for (int i = 0; i < 100; ++i)
                sink({modsynth::run::Stage::Search,
                      "a progress line of some length, number " + std::to_string(i), 0.1 * i});
            try {
                progress.finish();
            } catch (const modsynth::io::WriteError& e) {
                const std::string what = e.what();
                code = what.find("--events " + path) != std::string::npos &&
                               what.find("incomplete") != std::string::npos
                           ? 0
                           : 2;
            }
            guard.claim();
        }
        _exit(code);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
    CHECK(fs::file_size(path) <= 2048);
    fs::remove_all(dir);
}
