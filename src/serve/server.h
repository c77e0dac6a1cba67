#pragma once
// `modsynth serve`: the web editor and its API on a local HTTP server, until
// SIGINT or SIGTERM. Solves and imports run in child processes
// (solve_jobs.h, import_runner.h); the server itself survives whatever a
// request holds, and stops within seconds of the signal.
#include <string>

#include "api_routes.h"
#include "import_runner.h"
#include "solve_jobs.h"

namespace modsynth::app {

struct ServerOptions {
    std::string host = "127.0.0.1";
    int port = 8080;  ///< 0: any free port (the one taken is printed)
    ApiSettings api;
    JobLimits jobs;
    ImportLimits imports;
};

/// Serves until SIGINT or SIGTERM; returns the exit code. Prints the URL on
/// stdout once listening, so that a script can wait for it and read the port.
int run_server(const ServerOptions& options);

}  // namespace modsynth::app
