#pragma once
// The one thread of the process that solves and explains. Ipopt (through
// MUMPS) is not safe to enter from two threads, nor from thread after
// thread, so every synthesis of the Python module runs here, one at a
// time, while the caller waits without the GIL; Python threads that solve
// at once take turns.
#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include <sys/types.h>

#include <modsynth/run/cancel.h>

namespace modsynth::python {

class SolverThread {
public:
    struct Job {
        std::function<void()> run;
        /// Cancelled when the module shuts down; none for work that
        /// cannot be cancelled (it then finishes first).
        std::optional<run::CancelToken> cancel;
    };

    /// The thread of this process, started on first use (and again in a
    /// child forked after it started, which has no copy of it).
    static SolverThread& instance();

    void submit(Job job);
    /// Cancels what runs and what waits, lets it all finish, and joins:
    /// at interpreter exit. Later submissions start a new thread.
    static void shut_down();

    SolverThread(const SolverThread&) = delete;
    SolverThread& operator=(const SolverThread&) = delete;
    ~SolverThread();

private:
    SolverThread();
    void loop();
    void stop();

    std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<Job> jobs_;
    std::optional<run::CancelToken> running_;
    bool stopping_ = false;
    std::thread thread_;
};

}  // namespace modsynth::python
