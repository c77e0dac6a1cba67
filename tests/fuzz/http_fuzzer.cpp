// The HTTP server on arbitrary bytes: the real routes behind the real
// connection handling, in this process, fed each input as one raw request
// on a loopback connection. Whatever the bytes, every reply must be a
// well-formed HTTP response with a status below 500, every error carries a
// JSON body, and the server keeps answering.
//
// Solves are started by a SolveJobs whose solver is /bin/false, so a fuzzed
// POST /api/solve runs the route to its end without running a solve; a
// fuzzed POST /api/import imports in this process.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <thread>

#include <nlohmann/json.hpp>

#include "api_routes.h"
#include "import_runner.h"
#include "solve_jobs.h"

// Last: it pulls in <resolv.h>.
#include "connection_server.h"

namespace {

using namespace modsynth::app;

// Far beyond what a reply needs on the loopback: a silence this long means
// the server stopped answering.
constexpr int kReplyTimeoutMs = 10'000;

/// A server that stopped answering is a hang, and a hang is found by where
/// its threads wait: their stacks (when gdb is at hand) and open descriptors.
void print_thread_stacks() {
    const std::string pid = std::to_string(::getpid());
    const std::string command = "{ ls -l /proc/" + pid +
                                "/fd; command -v gdb >/dev/null && gdb -p " + pid +
                                " -batch -nx -ex 'thread apply all bt 12' 2>/dev/null; } 1>&2";
    [[maybe_unused]] const int status = std::system(command.c_str());
}

[[noreturn]] void fail(const char* what, std::string_view reply) {
    std::fprintf(stderr, "http fuzzer: %s; reply (%zu bytes):\n%.*s\n", what, reply.size(),
                 static_cast<int>(std::min<std::size_t>(reply.size(), 2000)), reply.data());
    std::abort();
}

/// Each fuzzed POST /api/solve makes a job folder, and the fixture is never
/// destroyed, so its jobs never remove theirs: they all go under one folder
/// of this process's own, removed when it exits.
void keep_scratch_in_own_folder() {
    static std::string root =
        (std::filesystem::temp_directory_path() / "modsynth-http-fuzz.XXXXXX").string();
    if (!::mkdtemp(root.data())) fail("cannot make a scratch folder", {});
    ::setenv("TMPDIR", root.c_str(), 1);
    std::atexit([] {
        std::error_code ignored;
        std::filesystem::remove_all(root, ignored);
    });
}

struct Fixture {
    std::unique_ptr<SolveJobs> jobs;
    std::unique_ptr<ImportRunner> imports;
    std::unique_ptr<ConnectionServer> server;
    std::thread thread;
    int port = 0;

    Fixture() {
        keep_scratch_in_own_folder();
        JobLimits job_limits;
        job_limits.time_limit = 1.0;
        job_limits.grace = 0.5;
        jobs = std::make_unique<SolveJobs>(job_limits, "/bin/false");
        // Drawings are imported in this process, well within the time a
        // reply may take.
        ImportLimits import_limits;
        import_limits.time_limit = 2.0;
        imports = std::make_unique<ImportRunner>(import_limits, "");
        ConnectionLimits limits;
        limits.workers = 8;
        limits.head_timeout = 2.0;
        limits.read_timeout = 2.0;
        limits.write_timeout = 2.0;
        server = std::make_unique<ConnectionServer>(limits);
        ApiSettings api;
        api.max_body = 64 * 1024;
        api.max_streams = 4;
        api.max_streams_per_client = 2;
        server->set_payload_max_length(api.max_body);
        add_routes(*server, *jobs, api, imports.get());
        port = server->bind_to_any_port("127.0.0.1");
        if (port <= 0) fail("cannot bind the server", {});
        thread = std::thread([this] { server->listen_after_bind(); });
    }
};

// libFuzzer's timer (SIGALRM, for -timeout) interrupts system calls now and
// then: each call below is repeated on EINTR, never taken for an answer.

int connect_to(int port) {
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(static_cast<std::uint16_t>(port));
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    for (;;) {
        const int sock = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
        if (sock < 0) fail("cannot make a socket", {});
        if (::connect(sock, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0) return sock;
        const int err = errno;
        ::close(sock);
        if (err != EINTR) fail("cannot connect to the server", {});
    }
}

/// poll() on one descriptor until something happens or `deadline` passes (0).
int poll_until(pollfd& p, std::chrono::steady_clock::time_point deadline) {
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        const int n = ::poll(&p, 1, static_cast<int>(std::max<long long>(0, left.count())));
        if (n >= 0 || errno != EINTR) return n;
    }
}

/// Sends everything (the server drains what it does not read) while
/// collecting what comes back, then reads to the end.
std::string exchange(int port, std::string_view request) {
    using Clock = std::chrono::steady_clock;
    const int sock = connect_to(port);
    std::string reply;
    std::size_t sent = 0;
    bool write_open = true;
    char buf[16384];
    auto deadline = Clock::now() + std::chrono::milliseconds(kReplyTimeoutMs);
    for (;;) {
        if (write_open && sent == request.size()) {
            ::shutdown(sock, SHUT_WR);
            write_open = false;
        }
        pollfd p{sock, static_cast<short>(POLLIN | (write_open ? POLLOUT : 0)), 0};
        if (poll_until(p, deadline) <= 0) {
            print_thread_stacks();
            fail("the server stopped answering", reply);
        }
        if (p.revents & POLLIN || p.revents & (POLLHUP | POLLERR)) {
            const auto n = ::recv(sock, buf, sizeof buf, 0);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) break;
            reply.append(buf, static_cast<std::size_t>(n));
        } else if (p.revents & POLLOUT) {
            const auto n = ::send(sock, request.data() + sent, request.size() - sent, MSG_NOSIGNAL);
            if (n < 0 && errno == EINTR) continue;
            if (n < 0) {
                write_open = false;  // the server closed: its reply is what matters
            } else {
                sent += static_cast<std::size_t>(n);
            }
        }
        deadline = Clock::now() + std::chrono::milliseconds(kReplyTimeoutMs);
    }
    ::close(sock);
    return reply;
}

/// Checks the reply to the first request (later ones, to pipelined
/// requests, cannot be told apart without knowing which were HEAD).
void check_reply(std::string_view request, std::string_view reply) {
    if (reply.empty()) {
        // Only a request with no line at all goes unanswered.
        if (request.find_first_not_of("\r\n") == std::string_view::npos) return;
        fail("no reply", reply);
    }
    // Informational replies (100 Continue) come before the answer.
    std::string_view rest = reply;
    while (rest.substr(0, 9) == "HTTP/1.1 " && rest.size() > 9 && rest[9] == '1') {
        const auto end = rest.find("\r\n\r\n");
        if (end == std::string_view::npos) fail("an unfinished informational reply", reply);
        rest.remove_prefix(end + 4);
    }
    if (rest.size() < 12 || rest.substr(0, 9) != "HTTP/1.1 ") fail("not an HTTP response", reply);
    const int status = std::atoi(std::string(rest.substr(9, 3)).c_str());
    if (status < 200 || status > 599) fail("no status code", reply);
    if (status >= 500) fail("a server error", reply);
    const auto head_end = rest.find("\r\n\r\n");
    if (head_end == std::string_view::npos) fail("a reply head without its end", reply);
    const std::string_view head = rest.substr(0, head_end + 2);
    const std::string_view body_and_more = rest.substr(head_end + 4);
    // A compressed body (Accept-Encoding) is not looked into.
    const bool compressed = head.find("\r\nContent-Encoding: ") != std::string_view::npos;
    // httplib takes the method from the line's first word, also in a line
    // it then refuses: a reply to HEAD has no body even then.
    const bool head_request = request.substr(0, request.find_first_of(" \r\n")) == "HEAD";
    if (status >= 400 && !head_request && !compressed) {
        if (head.find("Content-Type: application/json\r\n") == std::string_view::npos)
            fail("an error reply that is not JSON", reply);
        const auto length_at = head.find("Content-Length: ");
        if (length_at == std::string_view::npos) fail("an error reply without its length", reply);
        const auto length =
            std::strtoull(std::string(head.substr(length_at + 16, 20)).c_str(), nullptr, 10);
        if (length > body_and_more.size()) fail("an error reply cut short", reply);
        const auto doc = nlohmann::json::parse(body_and_more.substr(0, length), nullptr, false);
        if (!doc.is_object() || !doc.contains("error") || !doc["error"].is_string())
            fail("an error reply without a JSON error message", reply);
    }
}

/// Made at the first input; under libFuzzer never destroyed (its threads
/// run until the process ends), in a replay stopped by the teardown.
Fixture*& the_fixture() {
    static Fixture* fixture = nullptr;
    return fixture;
}

}  // namespace

extern "C" void modsynth_fuzz_teardown() {
    Fixture* f = the_fixture();
    if (!f) return;
    f->server->stop();
    f->thread.join();
    f->server.reset();  // its room and workers end with it
    f->imports.reset();
    f->jobs.reset();
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (!the_fixture()) the_fixture() = new Fixture;
    Fixture& fixture = *the_fixture();
    const std::string_view request(reinterpret_cast<const char*>(data), size);
    check_reply(request, exchange(fixture.port, request));
    // Whatever that did, the next request is answered.
    const std::string info = exchange(
        fixture.port, "GET /api/info HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n");
    if (info.rfind("HTTP/1.1 200 ", 0) != 0) fail("the server stopped serving /api/info", info);
    return 0;
}
