#include "api_routes.h"

#include <modsynth/drawing/import.h>
#include <modsynth/io/check_timeout.h>
#include <modsynth/io/input.h>
#include <modsynth/io/task_document.h>
#include <modsynth/io/task_io.h>
#include <modsynth/text/format.h>
#include <modsynth/text/printable.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <regex>
#include <sstream>
#include <variant>

#include "import_runner.h"
#include "loopback.h"
#include "solve_jobs.h"
#include "stream_slots.h"
#include "web_assets.h"

// Last: it pulls in <resolv.h>, whose `_res` macro breaks Eigen's headers.
#include <httplib.h>

namespace modsynth::app {
namespace {

using httplib::Request;
using httplib::Response;
using nlohmann::json;

// A long poll or a progress stream waits this long for news before it says
// it is still there (a stream) or answers unchanged (a poll).
constexpr auto kHeartbeat = std::chrono::milliseconds(1000);
constexpr double kLongestPoll = 20.0;
/// Seconds a request's worker may spend checking a task's geometry (a long
/// helix among many obstacles takes minutes): a worker is never held
/// longer, whether the client waits or has left. A solve's child process
/// checks the task again within the job's own time limit.
constexpr double kCheckSeconds = 5.0;
// What a POST may name: a request body is read only for these.
const std::regex kPostRoutes(R"(/api/validate|/api/solve|/api/import|/api/jobs/[0-9a-f]+/cancel)");
// Longer paths name nothing here; refusing them early also spares the route
// patterns (std::regex recurses once per character).
constexpr std::size_t kLongestPath = 1024;
// Request text echoed in a reply is cut here: enough for any message the
// routes write, never a megabyte of a body quoted back.
constexpr std::size_t kEchoChars = 2000;
// The placement `modsynth import` takes: --width and --scale at most this,
// --at and --base coordinates at most this far out.
constexpr double kLargestScale = 1e9;
constexpr double kFarthestPoint = 1e9;

std::string printable(std::string_view text) { return text::printable(text, kEchoChars); }

// ------------------------------------------------------------------ replies

void send_json(Response& res, int status, const json& body) {
    res.status = status;
    res.set_header("Cache-Control", "no-store");
    // Text from a request is made printable before it gets here; replacing
    // what is still not UTF-8 only keeps a slip from becoming an exception.
    res.set_content(body.dump(1, ' ', false, json::error_handler_t::replace), "application/json");
}

void send_error(Response& res, int status, const std::string& message,
                const std::string& part = {}) {
    json body = {{"error", printable(message)}};
    if (!part.empty()) body["part"] = printable(part);
    send_json(res, status, body);
}

/// An error after which the connection closes: the rest of the request (a
/// body left unread) must not be taken for the next one.
void send_final_error(Response& res, int status, const std::string& message) {
    res.set_header("Connection", "close");
    send_error(res, status, message);
}

/// Makes httplib send the whole reply whatever the Range header asked: the
/// files here are small, and a slice of a JSON reply (an error above all)
/// is of no use. The Request is httplib's own non-const object, handed to
/// the handlers as const; clearing its parsed ranges is what httplib reads.
void ignore_ranges(const Request& req) { const_cast<Request&>(req).ranges.clear(); }

bool equals_ignoring_case(const std::string& a, const std::string& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

/// "application/json", in any case, with or without parameters such as
/// "; charset=utf-8".
bool is_json_type(const std::string& content_type) {
    std::string type = content_type.substr(0, content_type.find(';'));
    const auto first = type.find_first_not_of(" \t");
    const auto last = type.find_last_not_of(" \t");
    type = first == std::string::npos ? "" : type.substr(first, last - first + 1);
    return equals_ignoring_case(type, "application/json");
}

/// What a drawing is sent as to /api/import. None of these is a type a
/// cross-site form may send without a preflight, as with JSON.
bool is_drawing_type(const std::string& content_type) {
    if (is_json_type(content_type)) return false;
    std::string type = content_type.substr(0, content_type.find(';'));
    type.erase(0, std::min(type.size(), type.find_first_not_of(" \t")));
    type.erase(type.find_last_not_of(" \t") + 1);
    for (const char* t :
         {"image/svg+xml", "application/dxf", "image/vnd.dxf", "application/octet-stream"})
        if (equals_ignoring_case(type, t)) return true;
    return false;
}

std::string status_text(int status, const ApiSettings& settings, const Request& req) {
    switch (status) {
        case 400:
            return "bad request";
        case 404:
            return "nothing at " + printable(req.path);
        case 405:
            return "method not allowed";
        case 413:
            return "request body larger than " + std::to_string(settings.max_body) + " bytes";
        case 414:
            return "request URI too long";
        default:
            return "HTTP " + std::to_string(status);
    }
}

// --------------------------------------------------------------- job views

std::string job_path(const std::string& id) { return "/api/jobs/" + id; }

json outcome_json(const SolveOutcome& o) {
    json out = {{"status", to_string(o.status)}, {"exit_code", o.exit_code},
                {"seconds", o.seconds},          {"name", o.name},
                {"message", o.message},          {"core", o.core}};
    out["dof"] = o.dof ? json(*o.dof) : json(nullptr);
    out["total_link_length"] = o.total_link_length ? json(*o.total_link_length) : json(nullptr);
    out["clearance_margin"] = o.clearance_margin ? json(*o.clearance_margin) : json(nullptr);
    out["motion_seconds"] = o.motion_seconds ? json(*o.motion_seconds) : json(nullptr);
    return out;
}

json job_json(const JobState& s) {
    const std::string self = job_path(s.id);
    json files = json::object();
    for (const auto& name : s.files) files[name] = self + "/files/" + name;
    return {
        {"id", s.id},
        {"phase", to_string(s.phase)},
        {"done", s.phase == Phase::Done},
        {"status", s.status ? json(to_string(*s.status)) : json(nullptr)},
        {"stage", s.stage},
        {"stages", s.stages},
        {"elapsed", std::round(s.elapsed * 1000.0) / 1000.0},
        {"time_limit", s.time_limit},
        {"version", s.version},
        {"log", s.log},
        {"result", s.outcome ? outcome_json(*s.outcome) : json(nullptr)},
        {"explanation", s.explanation ? *s.explanation : json(nullptr)},
        {"explanation_note", s.explanation_note},
        {"cancel_reason", s.cancel_reason},
        {"files", files},
        {"links", {{"self", self}, {"events", self + "/events"}, {"cancel", self + "/cancel"}}}};
}

// ------------------------------------------------------------------- input

/// The request body, read only up to `max` bytes whatever its framing
/// (httplib bounds a Content-Length, not a chunked body); nothing after
/// replying 413 or 400.
std::optional<std::string> read_capped_body(const Request& req, Response& res,
                                            const httplib::ContentReader& reader, std::size_t max) {
    std::string body;
    // Without a length or chunks a request has no body (RFC 9112, 6.3).
    if (!req.has_header("Content-Length") && !req.has_header("Transfer-Encoding")) return body;
    bool too_large = false;
    const bool read = reader([&](const char* data, std::size_t size) {
        if (body.size() + size > max) {
            too_large = true;
            return false;
        }
        body.append(data, size);
        return true;
    });
    if (read) return body;
    if (too_large || res.status == 413) {
        send_final_error(res, 413, "request body larger than " + std::to_string(max) + " bytes");
    } else {
        send_final_error(res, 400, "the request body could not be read");
    }
    return std::nullopt;
}

/// The request body as JSON, or nothing after replying 400 with where the
/// syntax breaks.
std::optional<json> read_body(const std::string& text, Response& res) {
    try {
        return io::parse_json_text(text);
    } catch (const task::InputError& e) {
        send_error(res, 400, e.what());
    }
    return std::nullopt;
}

/// A positive number from the query string, at most `largest`; nothing when
/// absent. Throws task::InputError naming the parameter when it is not one.
/// The one value of a query parameter. One given twice is refused: which
/// of its values would count is a guess the client cannot see.
std::string query_text(const Request& req, const char* name) {
    const std::size_t n = req.get_param_value_count(name);
    if (n > 1) throw task::InputError(name, "given " + std::to_string(n) + " times; give it once");
    return req.get_param_value(name);
}

/// A decimal number as a person writes it ("0.5", "-2", "1e-3"), nothing
/// else: std::stod alone also takes hexadecimal ("0x10"), "inf", "nan" and
/// leading spaces.
bool decimal(const std::string& text, double& v) {
    static const std::regex kDecimal(R"([+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?)");
    if (text.size() > 64 || !std::regex_match(text, kDecimal)) return false;
    try {
        std::size_t used = 0;
        v = std::stod(text, &used);
        return used == text.size();
    } catch (const std::exception&) {
        return false;
    }
}

std::optional<double> query_number(const Request& req, const char* name,
                                   double largest = std::numeric_limits<double>::max()) {
    if (!req.has_param(name)) return std::nullopt;
    const std::string text = query_text(req, name);
    double v = 0.0;
    if (!decimal(text, v) || !std::isfinite(v) || v <= 0.0)
        throw task::InputError(name, "not a positive number: '" + printable(text) + "'");
    if (v > largest)
        throw task::InputError(name, text::format("%g is more than the %g allowed", v, largest));
    return v;
}

/// Comma-separated numbers from the query string, exactly `count` of them,
/// each finite and at most `largest` in size; nothing when absent. Throws
/// task::InputError naming the parameter otherwise.
std::optional<std::vector<double>> query_numbers(
    const Request& req, const char* name, std::size_t count,
    double largest = std::numeric_limits<double>::max()) {
    if (!req.has_param(name)) return std::nullopt;
    const std::string text = query_text(req, name);
    std::vector<double> out;
    std::size_t at = 0;
    while (out.size() < count && at <= text.size()) {
        const std::size_t comma = std::min(text.find(',', at), text.size());
        const std::string item = text.substr(at, comma - at);
        double v = 0.0;
        if (!decimal(item, v) || !std::isfinite(v) || std::abs(v) > largest) break;
        out.push_back(v);
        at = comma + 1;
    }
    if (out.size() != count || at != text.size() + 1)
        throw task::InputError(name, "expected " + std::to_string(count) +
                                         " numbers separated by commas: '" + printable(text) + "'");
    return out;
}

/// A yes-or-no query parameter: 1 or true, 0 or false; false when absent.
/// Throws task::InputError naming the parameter otherwise.
bool query_switch(const Request& req, const char* name) {
    if (!req.has_param(name)) return false;
    const std::string text = query_text(req, name);
    if (text == "1" || text == "true") return true;
    if (text == "0" || text == "false") return false;
    throw task::InputError(name, "expected 1 or 0 (true or false), not '" + printable(text) + "'");
}

/// The names of a comma-separated list (DXF layers); none when absent.
/// Throws task::InputError naming the parameter for an empty name.
std::vector<std::string> query_names(const Request& req, const char* name) {
    std::vector<std::string> out;
    if (!req.has_param(name)) return out;
    const std::string text = query_text(req, name);
    for (std::size_t at = 0; at <= text.size();) {
        const std::size_t comma = std::min(text.find(',', at), text.size());
        if (comma == at)
            throw task::InputError(name,
                                   "expected names separated by commas: '" + printable(text) + "'");
        out.push_back(text.substr(at, comma - at));
        at = comma + 1;
    }
    return out;
}

bool host_is_loopback(const Request& req) {
    if (!req.has_header("Host")) return true;  // HTTP/1.0 clients send none
    if (req.get_header_value_count("Host") != 1) return false;
    return is_loopback_host_header(req.get_header_value("Host"), req.local_port);
}

// ------------------------------------------------------------------ routes

class Routes : public std::enable_shared_from_this<Routes> {
public:
    Routes(SolveJobs& jobs, const ApiSettings& settings, ImportRunner* imports)
        : jobs_(jobs),
          settings_(settings),
          streams_(settings.max_streams, settings.max_streams_per_client),
          own_imports_(imports ? nullptr : std::make_unique<ImportRunner>(ImportLimits{}, "")),
          imports_(imports ? *imports : *own_imports_) {}

    // Every handler holds the routes, so they live as long as the server.
    void install(httplib::Server& server) {
        auto self = shared_from_this();
        server.set_pre_routing_handler(
            [self](const Request& req, Response& res) { return self->guard(req, res); });
        server.Get("/api/info", [self](const Request&, Response& res) { self->info(res); });
        post(server, "/api/validate",
             [](const Request&, Response& res, const std::string& body) { validate(body, res); });
        post(server, "/api/solve",
             [self](const Request& req, Response& res, const std::string& body) {
                 self->solve(req, res, body);
             });
        post(server, "/api/import",
             [self](const Request& req, Response& res, const std::string& body) {
                 self->import_drawing(req, res, body);
             });
        server.Get(R"(/api/jobs/([0-9a-f]+))",
                   [self](const Request& req, Response& res) { self->job(req, res); });
        server.Get(R"(/api/jobs/([0-9a-f]+)/events)",
                   [self](const Request& req, Response& res) { self->events(req, res); });
        post(server, R"(/api/jobs/([0-9a-f]+)/cancel)",
             [self](const Request& req, Response& res, const std::string&) {
                 self->cancel(req, res);
             });
        server.Get(R"(/api/jobs/([0-9a-f]+)/files/([a-z.\-]+))",
                   [self](const Request& req, Response& res) { self->file(req, res); });
        server.Get(R"(/([A-Za-z0-9_\-]+\.[a-z]+)?)",
                   [](const Request& req, Response& res) { asset(req, res); });
        server.set_error_handler([self](const Request& req, Response& res) {
            ignore_ranges(req);  // also a Range that did not parse (416)
            if (res.body.empty())
                send_error(res, res.status, status_text(res.status, self->settings_, req));
        });
        server.set_exception_handler([](const Request&, Response& res, std::exception_ptr e) {
            std::string what = "unknown error";
            try {
                std::rethrow_exception(e);
            } catch (const std::exception& x) {
                what = x.what();
            } catch (...) {
            }
            send_error(res, 500, "internal error: " + what);
        });
    }

    /// A POST route whose handler gets the body, read within max_body.
    template <typename Handler>
    void post(httplib::Server& server, const std::string& pattern, Handler handler) {
        server.Post(
            pattern, [self = shared_from_this(), handler](const Request& req, Response& res,
                                                          const httplib::ContentReader& reader) {
                const auto body = read_capped_body(req, res, reader, self->settings_.max_body);
                if (body) handler(req, res, *body);
            });
    }

private:
    /// Refuses what no route should see: foreign Host names, and POST bodies
    /// that are not JSON (a cross-site form can send text/plain without
    /// asking; it cannot send application/json without a preflight this
    /// server never grants).
    /// Every refusal here closes the connection: the request's body, if
    /// any, is left unread.
    httplib::Server::HandlerResponse guard(const Request& req, Response& res) const {
        using R = httplib::Server::HandlerResponse;
        ignore_ranges(req);
        if (settings_.loopback_only && !host_is_loopback(req)) {
            send_final_error(res, 403,
                             "this server answers only on the loopback (Host: localhost, "
                             "127.0.0.1 or [::1], with its port or none)");
            return R::Handled;
        }
        if (req.method != "GET" && req.method != "HEAD" && req.method != "POST") {
            send_final_error(res, 405, "method " + req.method + " not allowed (GET or POST)");
            return R::Handled;
        }
        if (req.path.size() > kLongestPath) {
            send_final_error(
                res, 414,
                "request path longer than " + std::to_string(kLongestPath) + " characters");
            return R::Handled;
        }
        // httplib would read the body of a POST that no route takes, with
        // no bound when chunked: refuse it unread.
        if (req.method == "POST" && !std::regex_match(req.path, kPostRoutes)) {
            send_final_error(res, 404, "nothing to POST to at " + req.path);
            return R::Handled;
        }
        // This runs before the body is read: judge by the headers.
        const std::string length = req.get_header_value("Content-Length");
        const bool has_body =
            (!length.empty() && length != "0") || req.has_header("Transfer-Encoding");
        const bool drawing = req.path == "/api/import";
        const std::string type = req.get_header_value("Content-Type");
        if (req.method == "POST" && drawing && !is_drawing_type(type)) {
            send_final_error(res, 415,
                             "send the drawing as Content-Type: image/svg+xml, application/dxf "
                             "or application/octet-stream");
            return R::Handled;
        }
        if (req.method == "POST" && !drawing && (has_body || req.has_header("Content-Type")) &&
            !is_json_type(type)) {
            send_final_error(res, 415, "send the body as Content-Type: application/json");
            return R::Handled;
        }
        if (length.find_first_not_of("0123456789") != std::string::npos) {
            send_final_error(res, 400, "Content-Length is not a number of bytes");
            return R::Handled;
        }
        // A body announced too large is refused before any of it is read.
        if (!length.empty() && (length.size() > 19 || std::stoull(length) > settings_.max_body)) {
            send_final_error(
                res, 413,
                "request body larger than " + std::to_string(settings_.max_body) + " bytes");
            return R::Handled;
        }
        return R::Unhandled;
    }

    void info(Response& res) {
        const JobLimits& l = jobs_.limits();
        // What a task's robot gets when it leaves a key out: the page starts
        // a new task from these instead of keeping copies.
        const task::RobotSpec d{};
        send_json(res, 200,
                  {{"name", "modsynth"},
                   {"version", MODSYNTH_VERSION},
                   {"max_solves", l.max_solves},
                   {"running", jobs_.running()},
                   {"time_limit", l.time_limit},
                   {"grace", l.grace},
                   {"client_timeout", l.client_timeout},
                   {"max_body", settings_.max_body},
                   {"robot_defaults",
                    {{"dof", d.dof},
                     {"link_diameter", d.link_diameter},
                     {"min_link_length", d.min_link_length},
                     {"max_link_length", d.max_link_length}}}});
    }

    static void validate(const std::string& body, Response& res) {
        const auto doc = read_body(body, res);
        if (!doc) return;
        try {
            // A spatial task is validated too: the editor edits it in 3-D.
            std::visit(
                [&](const auto& t) {
                    send_json(res, 200,
                              {{"valid", true},
                               {"name", t.name},
                               {"primitives", t.trajectory.size()},
                               {"obstacles", t.obstacles.size()},
                               {"base_regions", t.base_regions.size()},
                               {"errors", json::array()}});
                },
                io::parse_task_document(*doc, run::Deadline::in(kCheckSeconds)));
        } catch (const task::InputError& e) {
            send_json(res, 200,
                      {{"valid", false},
                       {"errors", json::array({{{"part", printable(e.part())},
                                                {"message", printable(e.what())}}})}});
        } catch (const io::CheckTimeout& e) {
            // Neither valid nor invalid: "checked": false says which.
            send_json(
                res, 200,
                {{"valid", false},
                 {"checked", false},
                 {"errors", json::array({{{"part", "(document)"},
                                          {"message", printable(text::format(
                                                          "not checked within the %g s a check may "
                                                          "take here: %s",
                                                          kCheckSeconds, e.what()))}}})}});
        }
    }

    /// A drawing (the file's bytes) to a task, as `modsynth import` makes
    /// it, with what a page needs to draw the original under it: the map
    /// from the file's page (SVG pixels, y down) to task metres. The import
    /// runs where it can be bounded and killed (import_runner.h).
    void import_drawing(const Request& req, Response& res, const std::string& body) {
        ImportRequest request;
        request.body = body;
        request.base.name = "drawing";
        drawing::ImportOptions& options = request.options;
        try {
            const std::string f = req.has_param("format") ? query_text(req, "format") : "";
            if (equals_ignoring_case(f, "dxf")) {
                request.format = drawing::DrawingFormat::Dxf;
            } else if (!equals_ignoring_case(f, "svg")) {
                throw task::InputError("format", "expected svg or dxf, not '" + printable(f) + "'");
            }
            if (req.has_param("name")) request.base.name = query_text(req, "name");
            request.spatial_base.name = request.base.name;
            // The ranges `modsynth import` takes.
            options.placement.width = query_number(req, "width", kLargestScale);
            options.placement.scale = query_number(req, "scale", kLargestScale);
            if (options.placement.width && options.placement.scale)
                throw task::InputError("scale", "give width or scale, not both");
            // On a surface in space, as `import --plane` / `--cylinder`.
            SurfaceImport& surface = request.surface;
            surface.plane_option = "plane";
            surface.cylinder_option = "cylinder";
            if (const auto p = query_numbers(req, "plane", 9, kFarthestPoint)) surface.plane = *p;
            if (const auto c = query_numbers(req, "cylinder", 7, kFarthestPoint))
                surface.cylinder = *c;
            if (!surface.plane.empty() && !surface.cylinder.empty())
                throw task::InputError("cylinder", "give plane or cylinder, not both");
            surface.check();
            if (surface.placed() && req.has_param("at"))
                throw task::InputError(
                    "at", "not with plane or cylinder: the drawing's centre goes to the surface");
            if (const auto at = query_numbers(req, "at", 2, kFarthestPoint))
                options.placement.at = geometry::Vec2((*at)[0], (*at)[1]);
            if (const auto r = query_numbers(req, "rotate", 1)) {
                if (std::abs((*r)[0]) > 3600.0)
                    throw task::InputError("rotate", "degrees within -3600 to 3600");
                options.placement.rotate_degrees = (*r)[0];
            }
            options.tolerance = query_number(req, "tolerance").value_or(options.tolerance);
            if (!(options.tolerance >= 1e-9 && options.tolerance <= 1.0))
                throw task::InputError("tolerance", "metres within 1e-9 to 1");
            // What is read, as `import --layers`, `--strict`, `--hatch-boundaries`.
            options.read.layers = query_names(req, "layers");
            options.read.strict = query_switch(req, "strict");
            options.read.hatch_boundaries = query_switch(req, "hatch_boundaries");
            if (surface.placed()) {
                // In space a base region is a box; round a cylinder the
                // drawing faces its centre.
                if (const auto b = query_numbers(req, "base", 6, kFarthestPoint)) {
                    const auto& v = *b;
                    if (!(v[0] <= v[3]) || !(v[1] <= v[4]) || !(v[2] <= v[5]))
                        throw task::InputError(
                            "base", "expected a box xmin,ymin,zmin,xmax,ymax,zmax with min <= max");
                    request.spatial_base.base_regions.push_back(
                        {geometry::Vec3(v[0], v[1], v[2]), geometry::Vec3(v[3], v[4], v[5])});
                }
            } else if (const auto b = query_numbers(req, "base", 4, kFarthestPoint)) {
                const auto& v = *b;
                if (!(v[0] <= v[2]) || !(v[1] <= v[3]))
                    throw task::InputError("base", "expected xmin,ymin,xmax,ymax with min <= max");
                request.base.base_regions.push_back(
                    {geometry::Vec2(v[0], v[1]), geometry::Vec2(v[2], v[3])});
            }
        } catch (const task::InputError& e) {
            return send_error(res, 400, e.what(), e.part());
        }
        const ImportReply reply = imports_.run(request);
        if (reply.retry_later) res.set_header("Retry-After", "5");
        if (reply.status != 200) {
            const json& b = reply.body;
            return send_error(
                res, reply.status,
                b.contains("error") && b["error"].is_string() ? b["error"].get<std::string>()
                                                              : std::string("the import failed"),
                b.contains("part") && b["part"].is_string() ? b["part"].get<std::string>()
                                                            : std::string());
        }
        send_json(res, 200, reply.body);
    }

    void solve(const Request& req, Response& res, const std::string& body) {
        const auto doc = read_body(body, res);
        if (!doc) return;
        double time_limit = 0.0;
        try {
            // Either kind: the child `modsynth solve` (and `explain`) take both.
            // A task whose checks take longer than a worker may spend goes
            // to the job, which checks it within its own time limit and can
            // be cancelled.
            try {
                io::parse_task_document(*doc, run::Deadline::in(kCheckSeconds));
            } catch (const io::CheckTimeout&) {
            }
            time_limit = query_number(req, "time_limit").value_or(0.0);
        } catch (const task::InputError& e) {
            send_error(res, e.part() == "time_limit" ? 400 : 422, e.what(), e.part());
            return;
        }
        try {
            const std::string id = jobs_.start(doc->dump(1), time_limit);
            res.set_header("Location", job_path(id));
            send_json(res, 202, job_json(*jobs_.state(id)));
        } catch (const JobsBusy& e) {
            res.set_header("Retry-After", "5");
            send_error(res, 429, e.what());
        }
    }

    /// A poll; with ?since=VERSION a long poll that answers as soon as the
    /// job changes (or after ?wait seconds, at most kLongestPoll).
    void job(const Request& req, Response& res) {
        const std::string id = req.matches[1];
        std::optional<JobState> s;
        if (req.has_param("since")) {
            const std::uint64_t since =
                std::strtoull(req.get_param_value("since").c_str(), nullptr, 10);
            double wait = 10.0;
            try {
                wait = std::min(kLongestPoll, query_number(req, "wait").value_or(wait));
            } catch (const task::InputError& e) {
                send_error(res, 400, e.what(), e.part());
                return;
            }
            // Past the client's share of waiting workers, a poll answers now.
            const auto slot = streams_.acquire(req.remote_addr);
            if (!slot) wait = 0.0;
            s = jobs_.wait_for_change(id, since,
                                      std::chrono::milliseconds(static_cast<long>(wait * 1000)));
        } else {
            s = jobs_.state(id);
        }
        if (!s) return send_error(res, 404, "no job " + id);
        send_json(res, 200, job_json(*s));
    }

    /// Server-sent events: "state" with the whole job at every change,
    /// "tick" with the elapsed time in between. A stream that breaks means
    /// the page went away, so its solve is cancelled.
    void events(const Request& req, Response& res) {
        const std::string id = req.matches[1];
        if (!jobs_.state(id)) return send_error(res, 404, "no job " + id);
        auto slot = streams_.acquire(req.remote_addr);
        if (!slot) {
            res.set_header("Retry-After", "5");
            return send_error(res, 429,
                              "too many progress streams open (the most is " +
                                  std::to_string(streams_.per_client()) + " per client and " +
                                  std::to_string(streams_.total()) + " in all); poll " +
                                  job_path(id) + " instead");
        }
        auto seen = std::make_shared<std::optional<std::uint64_t>>();
        res.set_header("Cache-Control", "no-store");
        res.set_chunked_content_provider(
            "text/event-stream",
            // The provider holds the slot until the reply is gone.
            [self = shared_from_this(), id, seen, slot](std::size_t, httplib::DataSink& sink) {
                SolveJobs& jobs = self->jobs_;
                const auto s =
                    *seen ? jobs.wait_for_change(id, **seen, kHeartbeat) : jobs.state(id);
                if (!s) {
                    sink.done();
                    return true;
                }
                std::string message;
                if (!*seen || s->version != **seen || s->phase == Phase::Done) {
                    message = "event: state\ndata: " + job_json(*s).dump() + "\n\n";
                    *seen = s->version;
                } else {
                    message = "event: tick\ndata: " + json{{"elapsed", s->elapsed}}.dump() + "\n\n";
                }
                if (!sink.write(message.data(), message.size())) return false;
                if (s->phase == Phase::Done) sink.done();
                return true;
            },
            [self = shared_from_this(), id](bool completed) {
                if (!completed)
                    self->jobs_.cancel(id, "the client left: its progress stream closed");
            });
    }

    void cancel(const Request& req, Response& res) {
        const std::string id = req.matches[1];
        if (!jobs_.cancel(id, "cancelled by the client"))
            return send_error(res, 404, "no job " + id);
        send_json(res, 200, job_json(*jobs_.state(id)));
    }

    void file(const Request& req, Response& res) {
        const std::string id = req.matches[1], name = req.matches[2];
        const auto path = jobs_.file(id, name);
        if (!path) return send_error(res, 404, "job " + id + " has no file " + name);
        std::ifstream in(*path, std::ios::binary);
        std::ostringstream content;
        content << in.rdbuf();
        if (req.has_param("download"))
            res.set_header("Content-Disposition", "attachment; filename=\"" + name + "\"");
        res.set_header("Cache-Control", "no-store");
        res.set_content(content.str(), mime_of(name));
    }

    static void asset(const Request& req, Response& res) {
        const WebAsset* a = find_web_asset(req.path == "/" ? "/index.html" : req.path);
        if (!a) return send_error(res, 404, "nothing at " + req.path);
        res.set_header("Cache-Control", "no-cache");
        res.set_content(reinterpret_cast<const char*>(a->data), a->size, a->mime);
    }

    static const char* mime_of(const std::string& name) {
        const auto ends = [&](const char* ext) {
            const std::string e = ext;
            return name.size() >= e.size() &&
                   name.compare(name.size() - e.size(), e.size(), e) == 0;
        };
        if (ends(".json")) return "application/json";
        if (ends(".html")) return "text/html; charset=utf-8";
        if (ends(".md")) return "text/markdown; charset=utf-8";
        if (ends(".csv")) return "text/csv; charset=utf-8";
        if (ends(".urdf")) return "application/xml";
        if (ends(".yaml")) return "application/yaml; charset=utf-8";
        return "text/plain; charset=utf-8";
    }

    SolveJobs& jobs_;
    ApiSettings settings_;
    StreamSlots streams_;
    std::unique_ptr<ImportRunner> own_imports_;
    ImportRunner& imports_;
};

}  // namespace

void add_routes(httplib::Server& server, SolveJobs& jobs, const ApiSettings& settings,
                ImportRunner* imports) {
    std::make_shared<Routes>(jobs, settings, imports)->install(server);
}

}  // namespace modsynth::app
