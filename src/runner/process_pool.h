#pragma once
// Child processes run a few at a time, each under a hard wall-clock limit.
// Solves are isolated in processes because Ipopt is not thread-safe and Z3's
// default solver may ignore its own timeout: only a kill from outside bounds
// a run for sure.
#include <chrono>
#include <cstddef>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace modsynth::app {

struct ProcessSpec {
    std::vector<std::string> argv;  ///< argv[0] is the program's path
    std::string log_path;           ///< receives stdout and stderr; empty: /dev/null
    std::string stderr_path;        ///< when set, stderr goes here instead of log_path
    double wall_limit = 0.0;        ///< seconds before SIGKILL; <= 0: no limit
    std::string working_dir;        ///< where the child starts; empty: here
    /// Bytes of address space the child may take (RLIMIT_AS); 0: no limit.
    std::size_t memory_limit = 0;
};

struct ProcessResult {
    int exit_code = -1;      ///< exit status, or 128 + signal when killed (as shells do)
    int signal = 0;          ///< the terminating signal, 0 when it exited
    bool timed_out = false;  ///< killed by the watchdog
    double seconds = 0.0;    ///< wall clock from start to end
};

/// SIGINT or SIGTERM arrived while processes ran; they were killed.
class Interrupted : public std::runtime_error {
public:
    Interrupted() : std::runtime_error("interrupted") {}
};

using FinishHandler = std::function<void(std::size_t index, const ProcessResult& result)>;

/// Runs every spec, at most `jobs` at once, started in index order. on_finish
/// is called (in the caller's thread) as each one ends, on_tick a few times a
/// second so a caller can refresh a progress line. A process that cannot be
/// started ends with exit code 127, as in a shell.
void run_processes(const std::vector<ProcessSpec>& specs, int jobs, const FinishHandler& on_finish,
                   const std::function<void()>& on_tick = {});

/// One child process for a caller that supervises it itself, such as a
/// server that cannot block in run_processes: started like theirs, polled,
/// killed on demand or past its wall limit. Destroying a running one kills
/// and reaps it, so no child outlives its owner.
class ChildProcess {
public:
    explicit ChildProcess(const ProcessSpec& spec);
    ~ChildProcess();
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;

    /// False when it could not be started (poll() then gives exit code 127).
    bool started() const { return pid_ > 0; }
    /// The result once it has ended (reaped here), else nothing. A process
    /// past its wall limit is killed first and comes back timed_out.
    std::optional<ProcessResult> poll();
    /// SIGKILL, reap and return the result (the same result if it had ended).
    ProcessResult kill_now();
    double seconds() const;

private:
    int pid_ = -1;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point deadline_;
    std::optional<ProcessResult> result_;
};

/// Absolute path of the running executable, so that children run the very
/// same build.
std::string self_executable();

}  // namespace modsynth::app
