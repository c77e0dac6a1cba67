#include <memory>

#include "command.h"
#include "loopback.h"
#include "number_checks.h"
#include "server.h"

namespace modsynth::app {

Command add_serve(CLI::App& parent) {
    auto o = std::make_shared<ServerOptions>();
    CLI::App* sub = parent.add_subcommand(
        "serve", "Web task editor with live synthesis, on a local HTTP server (Ctrl-C stops)");
    sub->add_option("--port", o->port, "TCP port; 0 takes any free one (default 8080)")
        ->check(CLI::Range(0, 65535));
    sub->add_option("--host", o->host,
                    "address to listen on (default 127.0.0.1; other than the loopback, anyone "
                    "who can reach it can run solves)");
    sub->add_option("--max-solves", o->jobs.max_solves,
                    "solves running at once; more are refused with 429 (default 2)")
        ->check(CLI::Range(1, 64));
    sub->add_option("--time-limit", o->jobs.time_limit,
                    "seconds per solve: the default and the most a request may ask (default 60)")
        ->check(seconds());
    sub->add_option("--grace", o->jobs.grace,
                    "seconds past the time limit before a solve is killed (default 5)")
        ->check(seconds_or_zero());
    sub->add_option("--client-timeout", o->jobs.client_timeout,
                    "a solve whose client asks nothing for this many seconds is cancelled "
                    "(default 15)")
        ->check(seconds());
    return {sub, [o] {
                o->api.loopback_only = is_loopback_host(o->host);
                return run_server(*o);
            }};
}

}  // namespace modsynth::app
