#include "watchdog.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>

namespace modsynth::app {

Watchdog::Watchdog(double seconds, std::function<int()> on_expiry)
    : on_expiry_(std::move(on_expiry)) {
    const auto until = std::chrono::steady_clock::now() +
                       std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                           std::chrono::duration<double>(seconds));
    thread_ = std::thread([this, until] {
        std::unique_lock<std::mutex> lock(mutex_);
        if (wake_.wait_until(lock, until, [this] { return done_; })) return;
        lock.unlock();
        if (claimed_.exchange(true)) return;
        const int code = on_expiry_();
        std::fflush(stdout);
        std::fflush(stderr);
        // The other thread is inside a library call that cannot be
        // interrupted: end without unwinding it.
        std::_Exit(code);
    });
}

Watchdog::~Watchdog() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        done_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

void Watchdog::claim() {
    if (!claimed_.exchange(true)) return;
    // The watchdog is writing the answer and will end the process.
    for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
}

void Watchdog::set_stage(const std::string& stage) {
    std::lock_guard<std::mutex> lock(mutex_);
    stage_ = stage;
}

std::string Watchdog::stage() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return stage_;
}

}  // namespace modsynth::app
