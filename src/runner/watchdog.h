#pragma once
// The last line of defence of a command's time limit: the pipeline checks
// its deadline between and inside its stages, but a single library call
// (an Ipopt iteration, a Z3 check near its timeout) can overrun it. When the
// limit plus a margin has passed, the watchdog writes the command's answer
// for "stopped at the time limit" and ends the process; when the command
// finishes first, it claims its output and the watchdog stands down.
#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace modsynth::app {

class Watchdog {
public:
    /// After `seconds`, unless claim() came first: runs `on_expiry` (which
    /// writes what the command answers and returns its exit code), flushes
    /// stdout and stderr and ends the process with that code.
    Watchdog(double seconds, std::function<int()> on_expiry);
    ~Watchdog();
    Watchdog(const Watchdog&) = delete;
    Watchdog& operator=(const Watchdog&) = delete;

    /// The command writes its own output from now on. If the watchdog
    /// already writes it, this never returns: the process is about to end.
    void claim();

    /// What the command is doing, for the expiry message.
    void set_stage(const std::string& stage);
    std::string stage() const;

private:
    std::function<int()> on_expiry_;
    std::atomic<bool> claimed_{false};
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    bool done_ = false;
    std::string stage_ = "starting";
    std::thread thread_;
};

}  // namespace modsynth::app
