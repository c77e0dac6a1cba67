#pragma once
// The drawings a server imports for its clients (POST /api/import). Each
// import runs in a `modsynth import` process of its own, under a wall-clock
// limit and a memory limit: a drawing that would take long or much cannot
// hold a worker of the server or the server itself, and whatever the
// importer meets, the server survives it. Only so many run at once; a stop
// ends them all at once.
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <string>

#include <nlohmann/json.hpp>

#include <modsynth/drawing/import.h>
#include <modsynth/task/spatial_task.h>
#include <modsynth/task/task.h>

#include "surface_import.h"

namespace modsynth::app {

struct ImportLimits {
    std::size_t max_imports = 2;  ///< imports at once; more are refused (429)
    double time_limit = 20.0;     ///< seconds per import (its --time-limit)
    double grace = 2.0;           ///< seconds past the time limit before the kill
    /// Bytes of address space an import process may take.
    std::size_t memory_limit = std::size_t{2} << 30;
};

struct ImportRequest {
    drawing::DrawingFormat format = drawing::DrawingFormat::Svg;
    std::string body;                ///< the drawing file's bytes
    drawing::ImportOptions options;  ///< its deadline is the runner's to set
    task::Task base;                 ///< name and base regions of the task
    /// A drawing placed on a plane or round a cylinder in space: the task
    /// is spatial, its name and base boxes from `spatial_base`.
    SurfaceImport surface;
    task::SpatialTask spatial_base;
};

struct ImportReply {
    int status = 500;  ///< HTTP status: 200, 422, 429, 503 or 500
    nlohmann::json body;
    bool retry_later = false;  ///< 429 and 503: worth asking again
};

class ImportRunner {
public:
    /// `executable` is the modsynth binary that imports; empty: imports run
    /// in this process, bounded by their deadline only (for tests and
    /// fuzzing, which have no such binary).
    ImportRunner(const ImportLimits& limits, std::string executable);
    ImportRunner(const ImportRunner&) = delete;
    ImportRunner& operator=(const ImportRunner&) = delete;

    /// Imports one drawing and waits for the result: 200 with the reply of
    /// import_reply_json, 422 for a drawing that cannot be imported (within
    /// the limits), 429 when max_imports run already, 503 once stopped.
    ImportReply run(const ImportRequest& request);

    /// Ends the running imports (their callers answer 503 at once) and
    /// refuses new ones.
    void stop();

    const ImportLimits& limits() const { return limits_; }

private:
    ImportReply in_process(const ImportRequest& request);
    ImportReply in_child(const ImportRequest& request);

    ImportLimits limits_;
    std::string executable_;
    std::mutex mutex_;
    std::condition_variable stopped_;
    std::size_t running_ = 0;
    bool stopping_ = false;
};

}  // namespace modsynth::app
