#include "process_pool.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <thread>

extern char** environ;

namespace modsynth::app {
namespace {

using Clock = std::chrono::steady_clock;

// Polling, rather than waiting on SIGCHLD, keeps the signal handling to one
// flag; 10 ms is far below any solve's duration.
constexpr auto kPoll = std::chrono::milliseconds(10);
constexpr auto kTick = std::chrono::milliseconds(200);

volatile std::sig_atomic_t g_interrupted = 0;

extern "C" void note_interrupt(int) { g_interrupted = 1; }

// While children run, SIGINT and SIGTERM must not kill this process before it
// has killed them: a batch on a cluster node would leave orphans running.
class SignalGuard {
public:
    SignalGuard() {
        g_interrupted = 0;
        struct sigaction sa {};
        sa.sa_handler = note_interrupt;
        sigemptyset(&sa.sa_mask);
        sigaction(SIGINT, &sa, &old_int_);
        sigaction(SIGTERM, &sa, &old_term_);
    }
    ~SignalGuard() {
        sigaction(SIGINT, &old_int_, nullptr);
        sigaction(SIGTERM, &old_term_, nullptr);
    }
    SignalGuard(const SignalGuard&) = delete;
    SignalGuard& operator=(const SignalGuard&) = delete;

private:
    struct sigaction old_int_ {};
    struct sigaction old_term_ {};
};

struct Running {
    std::size_t index = 0;
    pid_t pid = -1;
    Clock::time_point start;
    Clock::time_point deadline = Clock::time_point::max();
};

double seconds_since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

// The child's side of spawn(), between fork and exec: only async-signal-safe
// calls. Exit code 127 when anything fails, as a shell reports a program it
// could not start.
[[noreturn]] void exec_child(const ProcessSpec& spec, char* const* argv, pid_t parent) {
    // A batch killed with SIGKILL cannot kill its children itself: the kernel
    // does it for it. The parent may already have died before prctl ran;
    // then this process has been reparented and must not start the program.
    if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || getppid() != parent) _exit(127);
    // A parent that blocks or ignores signals (a server does) must not pass
    // that on: a child should die of SIGINT, SIGTERM and SIGPIPE as usual.
    for (int sig : {SIGINT, SIGTERM, SIGPIPE}) signal(sig, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, nullptr);
    const char* log = spec.log_path.empty() ? "/dev/null" : spec.log_path.c_str();
    const int in = open("/dev/null", O_RDONLY);
    const int out = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = spec.stderr_path.empty()
                        ? out
                        : open(spec.stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (in < 0 || out < 0 || err < 0 || dup2(in, STDIN_FILENO) < 0 ||
        dup2(out, STDOUT_FILENO) < 0 || dup2(err, STDERR_FILENO) < 0)
        _exit(127);
    // Nothing else goes with the child: a server's connection inherited by
    // a solve would stay open until the solve ends, so its client would not
    // see it close (accept() gives sockets without close-on-exec).
    if (close_range(STDERR_FILENO + 1, ~0U, 0) != 0)
        for (int fd = STDERR_FILENO + 1, n = static_cast<int>(sysconf(_SC_OPEN_MAX)); fd < n; ++fd)
            close(fd);
    // After the opens, so that their relative paths mean the same as here.
    if (!spec.working_dir.empty() && chdir(spec.working_dir.c_str()) != 0) _exit(127);
    if (spec.memory_limit > 0) {
        const rlimit limit{spec.memory_limit, spec.memory_limit};
        if (setrlimit(RLIMIT_AS, &limit) != 0) _exit(127);
    }
    execve(argv[0], argv, environ);
    _exit(127);
}

// fork and exec rather than posix_spawn: only a child of fork can ask to
// die with its parent before it runs the program. Everything the child
// needs is prepared before the fork. The death signal is tied to the thread
// that forks; the callers fork from threads that outlive their children.
pid_t spawn(const ProcessSpec& spec) {
    std::vector<char*> argv;
    for (const auto& a : spec.argv) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const pid_t parent = getpid();
    const pid_t pid = fork();
    if (pid == 0) exec_child(spec, argv.data(), parent);
    return pid;
}

ProcessResult result_of(int status, const Running& r) {
    ProcessResult out;
    out.seconds = seconds_since(r.start);
    if (WIFEXITED(status)) {
        out.exit_code = WEXITSTATUS(status);
    } else if (WIFSIGNALED(status)) {
        out.signal = WTERMSIG(status);
        out.exit_code = 128 + out.signal;
    }
    return out;
}

int wait_blocking(pid_t pid) {
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return status;
}

void kill_all(std::vector<Running>& running) {
    for (const auto& r : running) kill(r.pid, SIGKILL);
    for (const auto& r : running) wait_blocking(r.pid);
    running.clear();
}

class Pool {
public:
    Pool(const std::vector<ProcessSpec>& specs, int jobs, const FinishHandler& on_finish)
        : specs_(specs),
          jobs_(static_cast<std::size_t>(std::max(1, jobs))),
          on_finish_(on_finish) {}

    bool busy() const { return next_ < specs_.size() || !running_.empty(); }

    void start_more() {
        while (running_.size() < jobs_ && next_ < specs_.size()) start(next_++);
    }

    void reap_finished() {
        for (std::size_t i = 0; i < running_.size();) {
            int status = 0;
            if (waitpid(running_[i].pid, &status, WNOHANG) == running_[i].pid) {
                finish(i, result_of(status, running_[i]));
            } else {
                ++i;
            }
        }
    }

    void kill_overdue() {
        const auto now = Clock::now();
        for (std::size_t i = 0; i < running_.size();) {
            if (now < running_[i].deadline) {
                ++i;
                continue;
            }
            kill(running_[i].pid, SIGKILL);
            ProcessResult r = result_of(wait_blocking(running_[i].pid), running_[i]);
            r.timed_out = true;
            finish(i, r);
        }
    }

    /// Until the next poll, or the next deadline if sooner, so that a tiny
    /// limit is enforced as given.
    void sleep() const {
        auto until = Clock::now() + kPoll;
        for (const auto& r : running_) until = std::min(until, r.deadline);
        std::this_thread::sleep_until(until);
    }

    void kill_everything() { kill_all(running_); }

private:
    void start(std::size_t index) {
        const ProcessSpec& spec = specs_[index];
        Running r;
        r.index = index;
        r.start = Clock::now();
        if (spec.wall_limit > 0.0)
            r.deadline = r.start + std::chrono::duration_cast<Clock::duration>(
                                       std::chrono::duration<double>(spec.wall_limit));
        r.pid = spawn(spec);
        if (r.pid < 0) {
            ProcessResult failed;
            failed.exit_code = 127;
            on_finish_(index, failed);
            return;
        }
        running_.push_back(r);
    }

    void finish(std::size_t slot, const ProcessResult& result) {
        const std::size_t index = running_[slot].index;
        running_.erase(running_.begin() + static_cast<long>(slot));
        on_finish_(index, result);
    }

    const std::vector<ProcessSpec>& specs_;
    std::size_t jobs_;
    const FinishHandler& on_finish_;
    std::vector<Running> running_;
    std::size_t next_ = 0;
};

Clock::time_point deadline_after(Clock::time_point start, double limit) {
    if (limit <= 0.0) return Clock::time_point::max();
    return start +
           std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limit));
}

}  // namespace

ChildProcess::ChildProcess(const ProcessSpec& spec)
    : start_(Clock::now()), deadline_(deadline_after(start_, spec.wall_limit)) {
    pid_ = spawn(spec);
    if (pid_ < 0) {
        result_ = ProcessResult{};
        result_->exit_code = 127;
    }
}

ChildProcess::~ChildProcess() {
    if (!result_) kill_now();
}

std::optional<ProcessResult> ChildProcess::poll() {
    if (result_) return result_;
    if (Clock::now() >= deadline_) {
        ProcessResult r = kill_now();
        result_->timed_out = true;
        r.timed_out = true;
        return r;
    }
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_)
        result_ = result_of(status, Running{0, pid_, start_});
    return result_;
}

ProcessResult ChildProcess::kill_now() {
    if (!result_) {
        kill(pid_, SIGKILL);
        result_ = result_of(wait_blocking(pid_), Running{0, pid_, start_});
    }
    return *result_;
}

double ChildProcess::seconds() const { return result_ ? result_->seconds : seconds_since(start_); }

void run_processes(const std::vector<ProcessSpec>& specs, int jobs, const FinishHandler& on_finish,
                   const std::function<void()>& on_tick) {
    SignalGuard guard;
    Pool pool(specs, jobs, on_finish);
    auto last_tick = Clock::now();
    try {
        while (pool.busy()) {
            if (g_interrupted) throw Interrupted();
            pool.start_more();
            pool.reap_finished();
            pool.kill_overdue();
            if (on_tick && Clock::now() - last_tick >= kTick) {
                on_tick();
                last_tick = Clock::now();
            }
            if (pool.busy()) pool.sleep();
        }
    } catch (...) {
        pool.kill_everything();
        throw;
    }
}

std::string self_executable() {
    std::error_code ec;
    const auto path = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::string("/proc/self/exe") : path.string();
}

}  // namespace modsynth::app
