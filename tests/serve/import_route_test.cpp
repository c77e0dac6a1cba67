// POST /api/import with a surface: a drawing placed on a plane or wrapped
// round a cylinder in space, as `modsynth import --plane` / `--cylinder`
// makes it, through the real routes on a loopback port (the import in this
// process); the surface's options refused by name.
#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "../support/fixtures.h"
#include "api_routes.h"
#include "import_runner.h"
#include "solve_jobs.h"

// Last: it pulls in <resolv.h>.
#include "connection_server.h"

namespace {

using namespace modsynth::app;
using nlohmann::json;

// A 100 x 50 mm frame with a rounded corner and a circle inside: lines, an
// arc and a circle, centred at (50, 25) mm.
constexpr const char* kDrawing =
    R"(<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="50mm" viewBox="0 0 100 50">)"
    R"(<path d="M 0 0 L 90 0 A 10 10 0 0 1 100 10 L 100 50 L 0 50 Z" fill="none" stroke="black"/>)"
    R"(<circle cx="50" cy="25" r="10" fill="none" stroke="black"/></svg>)";

const char* const kBase = "base=-0.05,-0.05,0.02,0.05,0.05,0.02";

class Server {
public:
    Server() {
        JobLimits job_limits;
        job_limits.time_limit = 1.0;
        jobs_ = std::make_unique<SolveJobs>(job_limits, "/bin/false");
        ImportLimits import_limits;
        import_limits.time_limit = 10.0;
        imports_ = std::make_unique<ImportRunner>(import_limits, "");
        ConnectionLimits limits;
        limits.workers = 2;
        server_ = std::make_unique<ConnectionServer>(limits);
        add_routes(*server_, *jobs_, ApiSettings{}, imports_.get());
        port_ = server_->bind_to_any_port("127.0.0.1");
        REQUIRE(port_ > 0);
        thread_ = std::thread([this] { server_->listen_after_bind(); });
    }
    ~Server() {
        server_->stop();
        thread_.join();
    }

    /// The status and the JSON body of a POST of the drawing.
    std::pair<int, json> import(const std::string& query) {
        return post("/api/import?format=svg&" + query, kDrawing, "image/svg+xml");
    }

    /// The same for a DXF file's text.
    std::pair<int, json> import_dxf(const std::string& query, const std::string& dxf) {
        return post("/api/import?format=dxf&" + query, dxf, "application/dxf");
    }

private:
    std::pair<int, json> post(const std::string& path, const std::string& body, const char* type) {
        httplib::Client client("127.0.0.1", port_);
        client.set_read_timeout(30, 0);
        const auto res = client.Post(path.c_str(), body, type);
        REQUIRE(res);
        return {res->status, json::parse(res->body)};
    }

    std::unique_ptr<SolveJobs> jobs_;
    std::unique_ptr<ImportRunner> imports_;
    std::unique_ptr<ConnectionServer> server_;
    std::thread thread_;
    int port_ = 0;
};

/// Every point of every primitive of a task's strokes (start, end, center).
template <typename F>
void each_point(const json& task, F f) {
    const json strokes =
        task.contains("strokes") ? task["strokes"] : json::array({task["trajectory"]});
    for (const auto& stroke : strokes)
        for (const auto& p : stroke)
            for (const char* key : {"start", "end"})
                if (p.contains(key)) f(p[key].get<std::vector<double>>());
}

}  // namespace

TEST_CASE("/api/import places a drawing on a plane in space") {
    Server s;
    const auto [status, body] =
        s.import("width=0.1&plane=0.4,0,0.25,0,-1,0,0,0,1&" + std::string(kBase) + "&name=wall");
    REQUIRE(status == 200);
    const json& task = body["task"];
    CHECK(task["space"] == "3d");
    CHECK(task["name"] == "wall");
    CHECK(body["surface"] == "plane");
    CHECK(body["underlay"].is_null());
    CHECK(body["tolerance"] == Approx(1e-4));
    CHECK(body["deviation"].get<double>() <= 1e-4);
    CHECK(task["base_regions"] ==
          json::array({{{"min", {-0.05, -0.05, 0.02}}, {"max", {0.05, 0.05, 0.02}}}}));
    // The wall x = 0.4, the drawing's centre at (0.4, 0, 0.25), its x along
    // -y: 10 cm wide, 5 cm high.
    int points = 0;
    double lo_y = 1, hi_y = -1, lo_z = 1, hi_z = -1;
    each_point(task, [&](const std::vector<double>& p) {
        ++points;
        CHECK(p[0] == Approx(0.4).margin(1e-9));
        lo_y = std::min(lo_y, p[1]), hi_y = std::max(hi_y, p[1]);
        lo_z = std::min(lo_z, p[2]), hi_z = std::max(hi_z, p[2]);
    });
    CHECK(points >= 6);
    CHECK(lo_y == Approx(-0.05).margin(1e-6));
    CHECK(hi_y == Approx(0.05).margin(1e-6));
    CHECK(lo_z == Approx(0.225).margin(1e-6));
    CHECK(hi_z == Approx(0.275).margin(1e-6));
    // The counts are those of the task.
    std::size_t primitives = 0;
    for (const auto& stroke : task["strokes"]) primitives += stroke.size();
    CHECK(body["primitives"] == primitives);
    CHECK(body["strokes"] == task["strokes"].size());
}

TEST_CASE("/api/import wraps a drawing round a cylinder in space") {
    Server s;
    const auto [status, body] =
        s.import("width=0.1&cylinder=0.4,0,0.25,0,0,1,0.08&" + std::string(kBase));
    REQUIRE(status == 200);
    CHECK(body["task"]["space"] == "3d");
    CHECK(body["surface"] == "cylinder");
    // The tolerance asked for, of which the import and the wrapping took half each.
    CHECK(body["tolerance"] == Approx(1e-4));
    CHECK(body["deviation"].get<double>() <= 1e-4);
    int points = 0;
    double nearest_x = 1;
    each_point(body["task"], [&](const std::vector<double>& p) {
        ++points;
        CHECK(std::hypot(p[0] - 0.4, p[1]) == Approx(0.08).margin(1e-9));
        CHECK(std::abs(p[2] - 0.25) <= 0.025 + 1e-9);
        nearest_x = std::min(nearest_x, p[0]);
    });
    CHECK(points >= 6);
    // The drawing faces the base box at the origin: on the cylinder's side
    // towards -x.
    CHECK(nearest_x < 0.4 - 0.07);
}

TEST_CASE("/api/import refuses a surface that is not one, naming the option") {
    Server s;
    const std::string base = "&" + std::string(kBase);
    const std::pair<std::string, std::string> cases[] = {
        {"plane=0.4,0,0.25,0,-1,0,0,0", "plane"},
        {"plane=0.4,0,0.25,0,-2,0,0,0,1", "plane"},
        {"plane=0.4,0,0.25,0,-1,0,0,-1,0", "plane"},
        {"cylinder=0.4,0,0.25,0,0,1,-0.08", "cylinder"},
        {"cylinder=0.4,0,0.25,0,0,0,0.08", "cylinder"},
        {"plane=0.4,0,0.25,0,-1,0,0,0,1&cylinder=0.4,0,0.25,0,0,1,0.08", "cylinder"},
        {"plane=0.4,0,0.25,0,-1,0,0,0,1&at=0.1,0.1", "at"},
        {"plane=0.4,0,0.25,0,-1,0,0,0,1&base=0,0,1,1", "base"},
        {"cylinder=0.4,0,0.25,0,0,1,0.08&base=0,0,0,1,1,-1", "base"},
    };
    for (const auto& [query, part] : cases) {
        INFO(query);
        const auto [status, body] = s.import("width=0.1&" + query);
        CHECK(status == 400);
        CHECK(body["part"] == part);
    }
    // A drawing wider than the cylinder's circumference: the import's
    // answer, naming the cylinder.
    const auto [status, body] = s.import("width=0.1&cylinder=0.4,0,0.25,0,0,1,0.01" + base);
    CHECK(status == 422);
    CHECK(body["part"] == "cylinder");
    CHECK(body["error"].get<std::string>().find("circumference") != std::string::npos);
    // A flat import still takes a base of four numbers.
    CHECK(s.import("width=0.1&base=-0.1,-0.1,0.1,0.1").first == 200);
}

TEST_CASE("/api/import reads DXF hatches, layers and strictness as `modsynth import` does") {
    std::ifstream in(modsynth::testing::source_path("tests/fixtures/drawings/hatches.dxf"));
    std::stringstream file;
    file << in.rdbuf();
    const std::string dxf = file.str();
    REQUIRE(!dxf.empty());
    Server s;
    const std::string placed = "width=0.1&at=0.35,0&base=-0.1,-0.1,0.1,0.1";
    // Hatches only: skipped by default, so nothing is left to draw.
    {
        const auto [status, body] = s.import_dxf(placed, dxf);
        CHECK(status == 422);
        CHECK_THAT(body["error"].get<std::string>(), Catch::Contains("HATCH"));
    }
    // Their boundaries, on request.
    std::size_t traced = 0;
    {
        const auto [status, body] = s.import_dxf(placed + "&hatch_boundaries=1", dxf);
        REQUIRE(status == 200);
        traced = body["primitives"].get<std::size_t>();
        CHECK(traced > 0);
        CHECK(body["warnings"].empty());
        CHECK(body["layers"].contains("outline"));
    }
    // Strict: a hatch not traced is refused; traced, it is not.
    CHECK(s.import_dxf(placed + "&strict=1", dxf).first == 422);
    {
        const auto [status, body] =
            s.import_dxf(placed + "&strict=true&hatch_boundaries=true", dxf);
        CHECK(status == 200);
        CHECK(body["primitives"].get<std::size_t>() == traced);
    }
    // Layers: the hatches' own layer keeps them, another leaves nothing.
    CHECK(s.import_dxf(placed + "&hatch_boundaries=1&layers=outline", dxf).first == 200);
    CHECK(s.import_dxf(placed + "&hatch_boundaries=1&layers=elsewhere", dxf).first == 422);
    // Values that are not one, named.
    const std::pair<std::string, std::string> bad[] = {
        {"hatch_boundaries=yes", "hatch_boundaries"},
        {"strict=2", "strict"},
        {"layers=outline,,other", "layers"},
        {"layers=", "layers"},
    };
    for (const auto& [query, part] : bad) {
        INFO(query);
        const auto [status, body] = s.import_dxf(placed + "&" + query, dxf);
        CHECK(status == 400);
        CHECK(body["part"] == part);
    }
}
