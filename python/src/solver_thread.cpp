#include "solver_thread.h"

#include <unistd.h>

namespace modsynth::python {

namespace {

std::mutex instance_mutex;
SolverThread* current = nullptr;
pid_t current_pid = 0;

}  // namespace

SolverThread& SolverThread::instance() {
    const std::lock_guard<std::mutex> lock(instance_mutex);
    // A forked child inherits the object but not its thread: the parent's
    // is left alone (joining it here would wait forever) and a new one
    // starts.
    if (current == nullptr || current_pid != ::getpid()) {
        current = new SolverThread();
        current_pid = ::getpid();
    }
    return *current;
}

void SolverThread::shut_down() {
    SolverThread* thread = nullptr;
    {
        const std::lock_guard<std::mutex> lock(instance_mutex);
        if (current_pid != ::getpid()) return;
        thread = current;
        current = nullptr;
    }
    delete thread;
}

SolverThread::SolverThread() : thread_([this] { loop(); }) {}

SolverThread::~SolverThread() { stop(); }

void SolverThread::submit(Job job) {
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        jobs_.push_back(std::move(job));
    }
    wake_.notify_one();
}

void SolverThread::stop() {
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
        if (running_) running_->cancel();
        for (const Job& job : jobs_)
            if (job.cancel) job.cancel->cancel();
    }
    wake_.notify_one();
    if (thread_.joinable()) thread_.join();
}

void SolverThread::loop() {
    for (;;) {
        Job job;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
            // Queued jobs still run when stopping (cancelled, they return
            // at once): each has a caller that waits for its answer.
            if (jobs_.empty()) return;
            job = std::move(jobs_.front());
            jobs_.pop_front();
            running_ = job.cancel;
        }
        job.run();
        const std::lock_guard<std::mutex> lock(mutex_);
        running_.reset();
    }
}

}  // namespace modsynth::python
