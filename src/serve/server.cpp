#include "server.h"

#include <pthread.h>
#include <signal.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <thread>

#include "exit_code.h"
#include "import_runner.h"
#include "loopback.h"
#include "process_pool.h"
#include "watchdog.h"

// Last: it pulls in <resolv.h>, whose `_res` macro breaks Eigen's headers.
#include "connection_server.h"

namespace modsynth::app {
namespace {

/// SIGINT and SIGTERM are blocked in every thread and taken by one waiting
/// thread, which stops the server; the rest of the shutdown is ordinary
/// destruction (SolveJobs kills its children). SIGPIPE is ignored: a client
/// that hangs up mid-reply must cost only its reply.
class ShutdownSignals {
public:
    ShutdownSignals() {
        signal(SIGPIPE, SIG_IGN);
        // A signal ignored when it is sent is dropped, blocked or not: a
        // server started where SIGINT is ignored (in the background of a
        // script) would never see it. Blocked, the default is never run.
        signal(SIGINT, SIG_DFL);
        signal(SIGTERM, SIG_DFL);
        sigemptyset(&set_);
        sigaddset(&set_, SIGINT);
        sigaddset(&set_, SIGTERM);
        pthread_sigmask(SIG_BLOCK, &set_, &old_);
    }
    ~ShutdownSignals() {
        release();
        pthread_sigmask(SIG_SETMASK, &old_, nullptr);
    }
    ShutdownSignals(const ShutdownSignals&) = delete;
    ShutdownSignals& operator=(const ShutdownSignals&) = delete;

    void stop_on_signal(httplib::Server& server) {
        waiter_ = std::thread([this, &server] {
            int sig = 0;
            sigwait(&set_, &sig);
            server.stop();  // harmless when it has stopped already
        });
    }

    /// Ends the waiting thread (waking it if no signal came); call while the
    /// server still exists.
    void release() {
        if (!waiter_.joinable()) return;
        pthread_kill(waiter_.native_handle(), SIGTERM);
        waiter_.join();
    }

private:
    sigset_t set_{};
    sigset_t old_{};
    std::thread waiter_;
};

// Workers beyond those that progress streams and long polls may hold.
constexpr std::size_t kFreeWorkers = 6;
// After SIGTERM the server stops within this even if some request is stuck:
// the process then ends without waiting for it (its children die with it).
constexpr double kLongestShutdown = 3.0;

std::string url_host(const std::string& host) {
    return host.find(':') != std::string::npos ? "[" + host + "]" : host;
}

}  // namespace

int run_server(const ServerOptions& options) {
    ShutdownSignals signals;
    std::optional<Watchdog> shutdown_limit;  // outlives everything below it
    SolveJobs jobs(options.jobs, self_executable());
    ImportRunner imports(options.imports, self_executable());
    // Progress streams and long polls hold a worker each; they get all but
    // a few, which stay free for the page's other requests.
    ApiSettings api = options.api;
    const auto solves = static_cast<std::size_t>(options.jobs.max_solves);
    api.max_streams = std::max(api.max_streams, 2 * solves + 4);
    api.max_streams_per_client = std::max(api.max_streams_per_client, solves + 2);
    ConnectionLimits limits;
    limits.workers = api.max_streams + kFreeWorkers;
    ConnectionServer server(limits);
    server.set_payload_max_length(api.max_body);
    add_routes(server, jobs, api, &imports);

    int port = options.port;
    errno = 0;
    const bool bound = port == 0 ? (port = server.bind_to_any_port(options.host)) > 0
                                 : server.bind_to_port(options.host, port);
    if (!bound) {
        if (errno == EADDRINUSE) {
            std::fprintf(stderr,
                         "error: port %d on %s is in use (another server runs there; choose "
                         "another --port, or 0 for any free one)\n",
                         options.port, options.host.c_str());
        } else {
            std::fprintf(stderr, "error: cannot listen on %s:%d%s%s\n", options.host.c_str(),
                         options.port, errno ? ": " : "", errno ? std::strerror(errno) : "");
        }
        return kInvalid;  // the --host or --port asked for cannot be had
    }
    if (!is_loopback_host(options.host)) {
        std::fprintf(stderr,
                     "warning: listening on %s: anyone who can reach it can run solves here\n",
                     options.host.c_str());
    }
    std::printf("modsynth serve: http://%s:%d/ (Ctrl-C stops)\n", url_host(options.host).c_str(),
                port);
    std::fflush(stdout);
    signals.stop_on_signal(server);
    server.listen_after_bind();
    shutdown_limit.emplace(kLongestShutdown, [] {
        std::printf("modsynth serve: stopped (requests still running were cut off)\n");
        return int{kOk};
    });
    // Whatever a worker waits for ends now: imports are killed, solves'
    // long polls and progress streams return.
    imports.stop();
    jobs.shutdown();
    signals.release();
    std::printf("modsynth serve: stopped\n");
    return kOk;
}

}  // namespace modsynth::app
