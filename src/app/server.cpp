#include "server.h"

#include <pthread.h>
#include <signal.h>

#include <cstdio>
#include <thread>

#include "command.h"
#include "process_pool.h"

// Last: it pulls in <resolv.h>, whose `_res` macro breaks Eigen's headers.
#include <httplib.h>

namespace modsynth::app {
namespace {

// A slow client must not hold a worker for long; a progress stream writes
// at least once a second, well within these.
constexpr time_t kReadTimeout = 10;
constexpr time_t kWriteTimeout = 10;

/// SIGINT and SIGTERM are blocked in every thread and taken by one waiting
/// thread, which stops the server; the rest of the shutdown is ordinary
/// destruction (SolveJobs kills its children). SIGPIPE is ignored: a client
/// that hangs up mid-reply must cost only its reply.
class ShutdownSignals {
public:
    ShutdownSignals() {
        signal(SIGPIPE, SIG_IGN);
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

std::string url_host(const std::string& host) {
    return host.find(':') != std::string::npos ? "[" + host + "]" : host;
}

}  // namespace

bool is_loopback_host(const std::string& host) {
    return host == "localhost" || host == "::1" || host.rfind("127.", 0) == 0;
}

int run_server(const ServerOptions& options) {
    ShutdownSignals signals;
    SolveJobs jobs(options.jobs, self_executable());
    httplib::Server server;
    // Progress streams hold a worker each for a whole solve; leave room for
    // them and for the page's other requests.
    const std::size_t workers = 16 + 2 * static_cast<std::size_t>(options.jobs.max_solves);
    server.new_task_queue = [workers] { return new httplib::ThreadPool(workers); };
    server.set_payload_max_length(options.api.max_body);
    server.set_read_timeout(kReadTimeout, 0);
    server.set_write_timeout(kWriteTimeout, 0);
    add_routes(server, jobs, options.api);

    int port = options.port;
    const bool bound = port == 0 ? (port = server.bind_to_any_port(options.host)) > 0
                                 : server.bind_to_port(options.host, port);
    if (!bound) {
        std::fprintf(stderr, "error: cannot listen on %s:%d\n", options.host.c_str(), options.port);
        return kInternal;
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
    signals.release();
    std::printf("modsynth serve: stopped\n");
    return kOk;
}

}  // namespace modsynth::app
