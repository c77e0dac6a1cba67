#include <modsynth/parts/external_tool.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>

#include <modsynth/text/format.h>

extern char** environ;

namespace modsynth::parts {

bool on_path(const std::string& program) {
    const char* path = std::getenv("PATH");
    if (!path) return false;
    std::stringstream folders(path);
    std::string folder;
    while (std::getline(folders, folder, ':')) {
        const std::string file = (folder.empty() ? "." : folder) + "/" + program;
        if (::access(file.c_str(), X_OK) == 0) return true;
    }
    return false;
}

ToolRun run_tool(const std::vector<std::string>& argv, double time_limit) {
    ToolRun run;
    char log_name[] = "/tmp/modsynth-tool-XXXXXX";
    const int log = ::mkstemp(log_name);
    if (log < 0) return run;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, log, STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, log, STDERR_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    pid_t pid = 0;
    const int spawned = ::posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(log);
    if (spawned == 0) {
        run.started = true;
        const auto deadline = std::chrono::steady_clock::now() +
                              std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                  std::chrono::duration<double>(time_limit));
        int status = 0;
        while (true) {
            const pid_t done = ::waitpid(pid, &status, WNOHANG);
            if (done == pid) break;
            if (done < 0) {
                run.started = false;
                break;
            }
            if (std::chrono::steady_clock::now() >= deadline) {
                ::kill(pid, SIGKILL);
                ::waitpid(pid, &status, 0);
                run.timed_out = true;
                break;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        if (!run.timed_out && WIFEXITED(status)) run.exit_code = WEXITSTATUS(status);
        // A program posix_spawnp could not exec exits 127 in the child.
        if (run.exit_code == 127) run.started = false;
    }
    std::ifstream in(log_name);
    std::ostringstream text;
    text << in.rdbuf();
    run.output = text.str();
    ::unlink(log_name);
    return run;
}

std::string AdmeshReport::summary() const {
    if (!parsed) return "admesh's report could not be read";
    return text::format(
        "%d part%s, %d disconnected facets, %d degenerate, %d edges fixed, %d facets added, "
        "%d reversed, %d backwards edges",
        parts, parts == 1 ? "" : "s", disconnected_facets, degenerate_facets, edges_fixed,
        facets_added, facets_reversed, backwards_edges);
}

AdmeshReport parse_admesh(const std::string& output) {
    AdmeshReport r;
    const auto figure = [&](const char* label, int& value) {
        const std::regex re(std::string(label) + R"(\s*:\s*(\d+))");
        std::smatch m;
        if (!std::regex_search(output, m, re)) return false;
        value = std::stoi(m[1]);
        return true;
    };
    r.parsed = figure("Total disconnected facets", r.disconnected_facets) &&
               figure("Number of parts", r.parts) &&
               figure("Degenerate facets", r.degenerate_facets) &&
               figure("Edges fixed", r.edges_fixed) && figure("Facets added", r.facets_added) &&
               figure("Facets reversed", r.facets_reversed) &&
               figure("Backwards edges", r.backwards_edges);
    return r;
}

}  // namespace modsynth::parts
