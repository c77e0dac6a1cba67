#pragma once
// A call into the pipeline as Python sees it: the work runs on the solver
// thread while the calling thread, without the GIL, waits in short slices;
// between them it hands the progress events to the Python callback (on the
// calling thread, as Python code expects) and looks for signals, so that
// Ctrl-C (KeyboardInterrupt) cancels a solve within a slice and the
// pipeline's reaction to its cancel token.
#include <chrono>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <utility>

#include <pybind11/pybind11.h>

#include <modsynth/run/cancel.h>
#include <modsynth/run/progress.h>

#include "solver_thread.h"

namespace modsynth::python {

namespace py = pybind11;

/// How often the waiting caller looks at the events and the signals.
inline constexpr std::chrono::milliseconds kWaitSlice{20};

/// True while a progress callback runs on this thread: a modsynth call made
/// from there would wait for the solver thread, which waits for the
/// callback.
bool& inside_callback();

template <class R>
struct CallState {
    std::mutex mutex;
    std::condition_variable changed;
    std::deque<run::ProgressEvent> events;
    bool started = false;
    bool abandoned = false;  ///< interrupted before it started: skip it
    bool done = false;
    std::optional<R> result;
    std::exception_ptr error;
};

/// Runs `work(sink)` on the solver thread and returns its result, or
/// rethrows its exception. `progress` (None for none) is called with each
/// event the work sends to the sink. On KeyboardInterrupt (or an exception
/// from `progress`) the token, when there is one, is cancelled and the work
/// awaited before the exception goes on; work without a token goes on in
/// the background, and the next call waits for it.
template <class R>
R call_on_solver_thread(std::function<R(const run::ProgressSink&)> work,
                        std::optional<run::CancelToken> cancel, const py::object& progress) {
    if (inside_callback())
        throw std::logic_error("modsynth cannot be called from a progress callback");
    auto state = std::make_shared<CallState<R>>();
    run::ProgressSink sink;
    if (!progress.is_none()) {
        sink = [state](const run::ProgressEvent& e) {
            {
                const std::lock_guard<std::mutex> lock(state->mutex);
                state->events.push_back(e);
            }
            state->changed.notify_all();
        };
    }
    SolverThread::Job job;
    job.cancel = cancel;
    job.run = [state, work = std::move(work), sink = std::move(sink)] {
        {
            const std::lock_guard<std::mutex> lock(state->mutex);
            if (state->abandoned) return;
            state->started = true;
        }
        std::optional<R> result;
        std::exception_ptr error;
        try {
            result.emplace(work(sink));
        } catch (...) {
            error = std::current_exception();
        }
        {
            const std::lock_guard<std::mutex> lock(state->mutex);
            state->result = std::move(result);
            state->error = error;
            state->done = true;
        }
        state->changed.notify_all();
    };
    {
        py::gil_scoped_release release;
        SolverThread::instance().submit(std::move(job));
    }

    const auto await_done = [&] {
        py::gil_scoped_release release;
        std::unique_lock<std::mutex> lock(state->mutex);
        state->changed.wait(lock, [&] { return state->done; });
    };
    std::optional<py::error_already_set> callback_error;
    for (;;) {
        std::deque<run::ProgressEvent> events;
        bool done = false;
        {
            py::gil_scoped_release release;
            std::unique_lock<std::mutex> lock(state->mutex);
            state->changed.wait_for(lock, kWaitSlice,
                                    [&] { return state->done || !state->events.empty(); });
            events.swap(state->events);
            done = state->done;
        }
        for (const run::ProgressEvent& e : events) {
            if (callback_error) break;
            inside_callback() = true;
            try {
                progress(e);
            } catch (py::error_already_set& err) {
                callback_error.emplace(std::move(err));
                if (cancel) cancel->cancel();
            }
            inside_callback() = false;
        }
        if (PyErr_CheckSignals() != 0) {
            py::error_already_set interrupted;
            bool started = false;
            {
                const std::lock_guard<std::mutex> lock(state->mutex);
                started = state->started;
                if (!started) state->abandoned = true;
            }
            if (started && cancel) {
                cancel->cancel();
                await_done();
            }
            throw interrupted;
        }
        if (done) break;
    }
    if (callback_error) throw std::move(*callback_error);
    if (state->error) std::rethrow_exception(state->error);
    return std::move(*state->result);
}

}  // namespace modsynth::python
