#pragma once
// What `modsynth serve` answers: the editor page and the JSON API it (and
// any script) talks to. The API is documented in README.md ("serve").
#include <cstddef>
#include <string>

namespace httplib {
class Server;
}

namespace modsynth::app {

class SolveJobs;
class ImportRunner;

struct ApiSettings {
    std::size_t max_body = 1 << 20;  ///< bytes; larger request bodies get 413
    /// Only Host headers naming the loopback are served, so that a page from
    /// elsewhere cannot reach the server through a rebound DNS name.
    bool loopback_only = true;
    /// Progress streams and long polls held open at once, by all clients
    /// and by one (one address); past the cap a stream gets 429 and a long
    /// poll answers at once.
    std::size_t max_streams = 16;
    std::size_t max_streams_per_client = 4;
};

/// Installs the page, the API routes and the error replies on `server`.
/// `jobs` and `imports` must outlive the server's listening; without
/// `imports`, drawings are imported in this process (ImportRunner's
/// default limits).
void add_routes(httplib::Server& server, SolveJobs& jobs, const ApiSettings& settings,
                ImportRunner* imports = nullptr);

}  // namespace modsynth::app
