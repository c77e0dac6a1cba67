#pragma once
// A request to stop a run from outside it (another thread, a signal
// handler's flag, a Python KeyboardInterrupt). Copies share one flag: the
// caller keeps a copy, hands another to the run (inside its run::Deadline),
// and cancel() on either is seen by every stage that polls the deadline.
#include <atomic>
#include <memory>

namespace modsynth::run {

class CancelToken {
public:
    CancelToken() : flag_(std::make_shared<std::atomic<bool>>(false)) {}

    /// Asks the run to stop; it returns its best answer so far ("unknown"
    /// when nothing is certified yet). Safe from any thread.
    void cancel() const { flag_->store(true, std::memory_order_relaxed); }
    bool cancelled() const { return flag_->load(std::memory_order_relaxed); }

private:
    friend class Deadline;
    std::shared_ptr<std::atomic<bool>> flag_;
};

}  // namespace modsynth::run
