#include "import_runner.h"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <utility>

#include <modsynth/io/atomic_file.h>
#include <modsynth/io/input.h>
#include <modsynth/task/input_error.h>
#include <modsynth/text/format.h>

#include "exit_code.h"
#include "imported_task.h"
#include "process_pool.h"
#include "temp_dir.h"

namespace modsynth::app {
namespace {

using nlohmann::json;

// How often a waiting import looks at its process; an import of the shipped
// drawings takes tens of milliseconds.
constexpr auto kPoll = std::chrono::milliseconds(10);
// A reply is a task of at most 5,000 primitives and a few figures.
constexpr std::size_t kLargestReply = 64u << 20;

json error_json(const std::string& message, const std::string& part = {}) {
    json body = {{"error", message}};
    if (!part.empty()) body["part"] = part;
    return body;
}

std::string number(double v) { return text::format("%.17g", v); }

std::string time_limit_text(double seconds) {
    return text::format("not imported within the time limit (%g s)", seconds);
}

/// The request's options as `modsynth import` takes them; each with its
/// value in one argument, so that a value starting with '-' stays a value.
std::vector<std::string> import_arguments(const ImportRequest& r, double time_limit) {
    const drawing::Placement& p = r.options.placement;
    const auto numbers = [](const std::vector<double>& v) {
        std::string out;
        for (double x : v) out += (out.empty() ? "" : ",") + number(x);
        return out;
    };
    const bool placed = r.surface.placed();
    std::vector<std::string> args = {"--time-limit=" + number(time_limit),
                                     "--tolerance=" + number(r.options.tolerance),
                                     "--rotate=" + number(p.rotate_degrees),
                                     "--name=" + (placed ? r.spatial_base.name : r.base.name)};
    if (p.width) args.push_back("--width=" + number(*p.width));
    if (p.scale) args.push_back("--scale=" + number(*p.scale));
    if (placed) {
        if (!r.surface.plane.empty()) args.push_back("--plane=" + numbers(r.surface.plane));
        if (!r.surface.cylinder.empty())
            args.push_back("--cylinder=" + numbers(r.surface.cylinder));
        for (const auto& b : r.spatial_base.base_regions)
            args.push_back("--base=" + numbers({b.min.x(), b.min.y(), b.min.z(), b.max.x(),
                                                b.max.y(), b.max.z()}));
    } else {
        if (p.at) args.push_back("--at=" + number(p.at->x()) + "," + number(p.at->y()));
        for (const auto& b : r.base.base_regions)
            args.push_back("--base=" + number(b.min.x()) + "," + number(b.min.y()) + "," +
                           number(b.max.x()) + "," + number(b.max.y()));
    }
    if (!r.options.read.obstacle_layer.empty())
        args.push_back("--obstacles-from=" + r.options.read.obstacle_layer);
    if (r.options.keep_order) args.push_back("--keep-order");
    if (!r.options.read.layers.empty()) {
        std::string layers;
        for (const std::string& l : r.options.read.layers)
            layers += (layers.empty() ? "" : ",") + l;
        args.push_back("--layers=" + layers);
    }
    if (r.options.read.strict) args.push_back("--strict");
    if (r.options.read.hatch_boundaries) args.push_back("--hatch-boundaries");
    return args;
}

/// The child names its options as the command line spells them (--plane,
/// --strict, ...); the reply names them as the request did.
json as_query_options(json reply, const SurfaceImport& surface) {
    const std::pair<std::string, std::string> names[] = {
        {"--plane", surface.plane_option},
        {"--cylinder", surface.cylinder_option},
        {"--layers", "layers"},
        {"--strict", "strict"},
        {"--hatch-boundaries", "hatch_boundaries"}};
    for (const char* key : {"part", "error"}) {
        if (!reply.contains(key) || !reply[key].is_string()) continue;
        std::string text = reply[key].get<std::string>();
        for (const auto& [cli, query] : names) {
            for (std::size_t at = text.find(cli); at != std::string::npos;
                 at = text.find(cli, at + query.size()))
                text.replace(at, cli.size(), query);
        }
        reply[key] = text;
    }
    return reply;
}

}  // namespace

ImportRunner::ImportRunner(const ImportLimits& limits, std::string executable)
    : limits_(limits), executable_(std::move(executable)) {}

ImportReply ImportRunner::run(const ImportRequest& request) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (stopping_) return {503, error_json("the server is shutting down"), true};
        if (running_ >= limits_.max_imports) {
            return {429,
                    error_json(std::to_string(running_) +
                               " imports are running, the most this server allows"),
                    true};
        }
        ++running_;
    }
    struct Slot {
        ImportRunner& runner;
        ~Slot() {
            std::lock_guard<std::mutex> lock(runner.mutex_);
            --runner.running_;
        }
    } slot{*this};
    return executable_.empty() ? in_process(request) : in_child(request);
}

void ImportRunner::stop() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    stopped_.notify_all();
}

ImportReply ImportRunner::in_process(const ImportRequest& request) {
    drawing::ImportOptions options = request.options;
    options.deadline =
        drawing::Clock::now() + std::chrono::duration_cast<drawing::Clock::duration>(
                                    std::chrono::duration<double>(limits_.time_limit));
    const SurfaceImport& surface = request.surface;
    const double tolerance = options.tolerance;
    const double wrap_tolerance = prepare_surface_import(options, surface);
    try {
        drawing::ImportResult r = drawing::import_drawing(request.body, request.format, options);
        if (!surface.placed()) return {200, import_reply_json(r, options, request.base)};
        const json task =
            surface_task_json(r, surface, request.spatial_base, wrap_tolerance, options.deadline);
        return {200, surface_import_reply_json(r, options, task, surface.kind(), tolerance)};
    } catch (const task::InputError& e) {
        return {422, error_json(e.what(), e.part())};
    } catch (const drawing::ImportTimeout& e) {
        return {422, error_json(time_limit_text(limits_.time_limit) + ": " + e.what())};
    }
}

ImportReply ImportRunner::in_child(const ImportRequest& request) {
    TempDir dir("modsynth-import");
    const std::string drawing_name =
        request.format == drawing::DrawingFormat::Dxf ? "drawing.dxf" : "drawing.svg";
    io::write_file_atomically(dir.path() + "/" + drawing_name, request.body);
    // The child runs in the folder and is given names, not paths: what it
    // answers must not tell where that is.
    ProcessSpec spec;
    spec.argv = {executable_, "import", drawing_name, "-o", "task.json", "--reply=reply.json"};
    for (auto& a : import_arguments(request, limits_.time_limit)) spec.argv.push_back(std::move(a));
    spec.log_path = dir.path() + "/import.log";
    spec.working_dir = dir.path();
    spec.wall_limit = limits_.time_limit + limits_.grace;
    spec.memory_limit = limits_.memory_limit;
    ChildProcess child(spec);
    std::optional<ProcessResult> result;
    while (!(result = child.poll())) {
        std::unique_lock<std::mutex> lock(mutex_);
        if (stopped_.wait_for(lock, kPoll, [this] { return stopping_; })) {
            lock.unlock();
            child.kill_now();
            return {503, error_json("the server is shutting down"), true};
        }
    }
    const auto reply = [&]() -> std::optional<json> {
        try {
            return json::parse(
                io::read_input_file(dir.path() + "/reply.json", "reply", kLargestReply));
        } catch (const std::exception&) {
            return std::nullopt;
        }
    }();
    if (result->timed_out) return {422, error_json(time_limit_text(limits_.time_limit))};
    if (result->signal == 0 && reply && reply->is_object()) {
        if (result->exit_code == kOk && reply->contains("task")) return {200, *reply};
        if ((result->exit_code == kInvalid || result->exit_code == kUnknown) &&
            reply->contains("error"))
            return {422, as_query_options(*reply, request.surface)};
    }
    // Anything else is the importer's failure, not the drawing's: its last
    // words say what happened.
    std::ifstream log(spec.log_path);
    std::string line, last;
    while (std::getline(log, line))
        if (!line.empty()) last = line;
    return {500, error_json(text::format("the import failed (exit %d): ", result->exit_code) +
                            (last.empty() ? "no message" : last))};
}

}  // namespace modsynth::app
