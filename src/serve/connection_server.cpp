#include "connection_server.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace modsynth::app {
namespace {

using Clock = std::chrono::steady_clock;

// A head longer than this is handed to a worker as it is, to be refused
// there: the polling thread only peeks at what has come.
constexpr std::size_t kPeekBytes = 64 * 1024;
// A closing connection drops what its client still sends for this long or
// this much, so that the client reads the reply instead of a reset.
constexpr auto kLinger = std::chrono::seconds(2);
constexpr std::size_t kLingerBytes = 8u << 20;
// Bodies are read in the room up to the server's payload limit and no
// further (past it a worker refuses them); chunked framing may add this
// much to a body of that size, and a chunk's size line this much.
constexpr std::size_t kLargestBody = 64u << 20;
constexpr std::size_t kChunkFraming = 64u << 10;
constexpr std::size_t kLongestChunkLine = 1024;
// Connections the kernel completes before they are accepted: more than the
// connection limit, so that a burst up to it is never left to SYN cookies
// (the kernel caps this at net.core.somaxconn).
constexpr int kListenBacklog = 1024;

Clock::time_point after(double seconds) {
    return Clock::now() +
           std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

int millis_until(Clock::time_point t) {
    const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(t - Clock::now()).count();
    return static_cast<int>(std::clamp<long long>(ms, 0, 60'000));
}

bool wait_for(int sock, short events, int timeout_ms) {
    pollfd p{sock, events, 0};
    for (;;) {
        const int n = ::poll(&p, 1, timeout_ms);
        if (n >= 0) return n > 0 && (p.revents & (events | POLLHUP | POLLERR));
        if (errno != EINTR) return false;
    }
}

void describe(const sockaddr_storage& addr, std::string& ip, int& port) {
    char text[INET6_ADDRSTRLEN] = "";
    if (addr.ss_family == AF_INET) {
        const auto& a = reinterpret_cast<const sockaddr_in&>(addr);
        inet_ntop(AF_INET, &a.sin_addr, text, sizeof text);
        port = ntohs(a.sin_port);
    } else if (addr.ss_family == AF_INET6) {
        const auto& a = reinterpret_cast<const sockaddr_in6&>(addr);
        inet_ntop(AF_INET6, &a.sin6_addr, text, sizeof text);
        port = ntohs(a.sin6_port);
    }
    ip = text;
}

/// A reply written without httplib, to a connection the workers never saw.
void reply_directly(int sock, int status, const char* reason, const std::string& message) {
    const std::string body = "{\"error\": \"" + message + "\"}";
    const std::string reply =
        "HTTP/1.1 " + std::to_string(status) + " " + reason +
        "\r\nContent-Type: application/json\r\nContent-Length: " + std::to_string(body.size()) +
        "\r\nConnection: close\r\n\r\n" + body;
    // Best effort: the socket buffer of a fresh connection takes it at once.
    [[maybe_unused]] const auto sent =
        ::send(sock, reply.data(), reply.size(), MSG_DONTWAIT | MSG_NOSIGNAL);
}

std::string seconds_text(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", seconds);
    return text;
}

bool contains_ignoring_case(std::string_view text, std::string_view lower_needle) {
    return std::search(text.begin(), text.end(), lower_needle.begin(), lower_needle.end(),
                       [](char a, char b) {
                           return std::tolower(static_cast<unsigned char>(a)) == b;
                       }) != text.end();
}

std::string_view trimmed(std::string_view v) {
    const auto b = v.find_first_not_of(" \t");
    if (b == std::string_view::npos) return {};
    return v.substr(b, v.find_last_not_of(" \t") - b + 1);
}

bool equals_ignoring_case(std::string_view a, std::string_view lower) {
    return a.size() == lower.size() && contains_ignoring_case(a, lower);
}

/// One header line of a request head: where it starts and ends (at its
/// CRLF) and its name and value.
struct HeaderLine {
    std::size_t begin = 0, end = 0;
    std::string_view name, value;
};

/// The header lines of a head (the request line and headers, each ending
/// in CRLF).
std::vector<HeaderLine> header_lines(std::string_view head) {
    std::vector<HeaderLine> out;
    std::size_t at = head.find("\r\n");
    while (at != std::string_view::npos && at + 2 < head.size()) {
        const std::size_t begin = at + 2;
        const std::size_t end = head.find("\r\n", begin);
        if (end == std::string_view::npos || end == begin) break;
        const std::string_view line = head.substr(begin, end - begin);
        const auto colon = line.find(':');
        if (colon != std::string_view::npos)
            out.push_back(
                {begin, end, trimmed(line.substr(0, colon)), trimmed(line.substr(colon + 1))});
        at = end;
    }
    return out;
}

/// How far the chunked framing of a body reaches.
struct ChunkScan {
    bool done = false;  ///< the last chunk and its trailers are in; `end` is where they end
    bool bad = false;   ///< not chunked framing: the worker says so
    std::size_t end = 0;
};

/// One request on a connection whose head has come: reads bounded by the
/// request's deadline, writes by the write timeout.
class RequestStream : public httplib::Stream {
public:
    /// `received`: what the waiting room already read of the request.
    RequestStream(int sock, const std::string& remote_ip, int remote_port,
                  const std::string& local_ip, int local_port, const ConnectionLimits& limits,
                  std::string received)
        : sock_(sock),
          remote_ip_(remote_ip),
          local_ip_(local_ip),
          remote_port_(remote_port),
          local_port_(local_port),
          read_deadline_(after(limits.read_timeout)),
          write_timeout_ms_(static_cast<int>(limits.write_timeout * 1000)),
          received_(std::move(received)) {}

    bool is_readable() const override {
        return taken_ < received_.size() || wait_for(sock_, POLLIN, millis_until(read_deadline_));
    }

    bool is_writable() const override {
        if (!wait_for(sock_, POLLOUT, write_timeout_ms_)) return false;
        // A client that hung up reads as end of file.
        char c;
        const auto n = ::recv(sock_, &c, 1, MSG_PEEK | MSG_DONTWAIT);
        return n > 0 || (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK));
    }

    ssize_t read(char* ptr, std::size_t size) override {
        if (taken_ < received_.size()) {
            const std::size_t n = std::min(size, received_.size() - taken_);
            std::memcpy(ptr, received_.data() + taken_, n);
            taken_ += n;
            return static_cast<ssize_t>(n);
        }
        for (;;) {
            const auto n = ::recv(sock_, ptr, size, MSG_DONTWAIT);
            if (n >= 0) return n;
            if (errno == EINTR) continue;
            if (errno != EAGAIN && errno != EWOULDBLOCK) return -1;
            if (!wait_for(sock_, POLLIN, millis_until(read_deadline_))) return -1;
        }
    }

    ssize_t write(const char* ptr, std::size_t size) override {
        for (;;) {
            const auto n = ::send(sock_, ptr, size, MSG_DONTWAIT | MSG_NOSIGNAL);
            if (n >= 0) {
                if (head_.size() < 8192) head_.append(ptr, std::min<std::size_t>(n, 8192));
                return n;
            }
            if (errno == EINTR) continue;
            if (errno != EAGAIN && errno != EWOULDBLOCK) return -1;
            if (!wait_for(sock_, POLLOUT, write_timeout_ms_)) return -1;
        }
    }

    void get_remote_ip_and_port(std::string& ip, int& port) const override {
        ip = remote_ip_;
        port = remote_port_;
    }
    void get_local_ip_and_port(std::string& ip, int& port) const override {
        ip = local_ip_;
        port = local_port_;
    }
    socket_t socket() const override { return sock_; }

    /// The reply said "Connection: close" (a handler may say so when it left
    /// part of the request unread), which httplib alone does not honour.
    bool reply_closes() const {
        const auto end = head_.find("\r\n\r\n");
        return contains_ignoring_case(head_.substr(0, end) + "\r\n", "\r\nconnection: close\r\n");
    }

private:
    int sock_;
    std::string remote_ip_, local_ip_;
    int remote_port_, local_port_;
    Clock::time_point read_deadline_;
    int write_timeout_ms_;
    std::string received_;  ///< read before the socket
    std::size_t taken_ = 0;
    std::string head_;  ///< the start of what was written: the reply's head
};

/// Follows a chunked body's framing in `c.received` from where it stopped.
template <class Connection>
ChunkScan scan_chunks(Connection& c, std::size_t largest_chunk) {
    const std::string& b = c.received;
    for (;;) {
        if (c.chunk_phase == 1) {  // a chunk's data and its CRLF
            const std::size_t come = b.size() - c.chunk_at;
            if (come < c.chunk_left) {
                c.chunk_at = b.size();
                c.chunk_left -= come;
                return {};
            }
            c.chunk_at += c.chunk_left;
            c.chunk_left = 0;
            c.chunk_phase = 0;
            continue;
        }
        const std::size_t eol = b.find("\r\n", c.chunk_at);
        if (eol == std::string::npos) {
            ChunkScan waiting;
            waiting.bad = b.size() - c.chunk_at > kLongestChunkLine;
            return waiting;
        }
        if (c.chunk_phase == 2) {  // trailers, up to an empty line
            if (eol == c.chunk_at) return {true, false, eol + 2};
            c.chunk_at = eol + 2;
            continue;
        }
        std::size_t size = 0, k = c.chunk_at;
        for (; k < eol && std::isxdigit(static_cast<unsigned char>(b[k])); ++k) {
            const char d = static_cast<char>(std::tolower(static_cast<unsigned char>(b[k])));
            size = size * 16 + static_cast<std::size_t>(d <= '9' ? d - '0' : d - 'a' + 10);
            if (size > largest_chunk) return {false, true, 0};
        }
        if (k == c.chunk_at) return {false, true, 0};
        c.chunk_at = eol + 2;
        c.chunk_phase = size == 0 ? 2 : 1;
        c.chunk_left = size + 2;
    }
}

/// Runs each accepted connection's task at once, in the accepting thread:
/// the task only hands the connection to the waiting room.
class InlineQueue : public httplib::TaskQueue {
public:
    void enqueue(std::function<void()> fn) override { fn(); }
    void shutdown() override {}
};

}  // namespace

ConnectionServer::ConnectionServer(const ConnectionLimits& limits) : limits_(limits) {
    new_task_queue = [] { return new InlineQueue; };
    // Not SO_REUSEPORT (httplib's default): a second server on the same port
    // must fail to bind rather than share the port's connections.
    set_socket_options([](socket_t sock) {
        int yes = 1;
        setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    });
    wake_fd_ = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
    if (wake_fd_ < 0) throw std::runtime_error(std::string("eventfd: ") + std::strerror(errno));
    room_ = std::thread([this] { wait_room(); });
    for (std::size_t i = 0; i < std::max<std::size_t>(limits_.workers, 1); ++i)
        workers_.emplace_back([this] { work(); });
}

ConnectionServer::~ConnectionServer() {
    stop();
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    const std::uint64_t one = 1;
    [[maybe_unused]] const auto w = ::write(wake_fd_, &one, sizeof one);
    ready_changed_.notify_all();
    room_.join();
    for (auto& t : workers_) t.join();
    for (auto& c : incoming_) close(c);
    for (auto& c : ready_) close(c);
    ::close(wake_fd_);
}

bool ConnectionServer::listen_after_bind() {
    // listen() again on a listening socket only sets its backlog.
    if (svr_sock_ != INVALID_SOCKET) ::listen(svr_sock_, kListenBacklog);
    return httplib::Server::listen_after_bind();
}

bool ConnectionServer::process_and_close_socket(socket_t sock) {
    if (open_ >= limits_.max_connections || sock >= FD_SETSIZE) {
        reply_directly(sock, 429, "Too Many Requests",
                       "too many open connections (the most is " +
                           std::to_string(limits_.max_connections) + ")");
        ::close(sock);
        return false;
    }
    ++open_;
    // A solve started while this connection is open must not inherit it.
    ::fcntl(sock, F_SETFD, FD_CLOEXEC);
    Connection c;
    c.sock = sock;
    sockaddr_storage addr{};
    socklen_t len = sizeof addr;
    if (getpeername(sock, reinterpret_cast<sockaddr*>(&addr), &len) == 0)
        describe(addr, c.remote_ip, c.remote_port);
    len = sizeof addr;
    if (getsockname(sock, reinterpret_cast<sockaddr*>(&addr), &len) == 0)
        describe(addr, c.local_ip, c.local_port);
    c.deadline = after(limits_.head_timeout);
    to_room(std::move(c));
    return true;
}

void ConnectionServer::to_room(Connection c) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!stopping_) {
            incoming_.push_back(std::move(c));
            c.sock = -1;
        }
    }
    if (c.sock >= 0) return close(c);
    const std::uint64_t one = 1;
    [[maybe_unused]] const auto w = ::write(wake_fd_, &one, sizeof one);
}

void ConnectionServer::close(Connection& c) {
    if (c.sock < 0) return;
    // shutdown acts on the connection, not on this descriptor: the client
    // learns of the end even while a copy of it is open elsewhere.
    ::shutdown(c.sock, SHUT_RDWR);
    ::close(c.sock);
    c.sock = -1;
    --open_;
}

void ConnectionServer::wait_room() {
    std::vector<Connection> waiting;
    std::vector<pollfd> fds;
    std::vector<char> peek(kPeekBytes);
    for (;;) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (stopping_) break;
            for (auto& c : incoming_) waiting.push_back(std::move(c));
            incoming_.clear();
        }
        fds.assign(1, pollfd{wake_fd_, POLLIN, 0});
        auto next = Clock::now() + std::chrono::seconds(1);
        for (const auto& c : waiting) {
            fds.push_back(pollfd{c.sock, static_cast<short>(POLLIN | POLLRDHUP), 0});
            next = std::min(next, c.deadline);
        }
        if (::poll(fds.data(), fds.size(), millis_until(next)) < 0 && errno != EINTR) break;
        if (fds[0].revents) {
            std::uint64_t count;
            [[maybe_unused]] const auto r = ::read(wake_fd_, &count, sizeof count);
        }
        const auto now = Clock::now();
        std::vector<Connection> still, ready;
        for (std::size_t i = 0; i < waiting.size(); ++i) {
            Connection& c = waiting[i];
            const short events = fds[i + 1].revents;
            if (c.draining) {
                bool done = now >= c.deadline;
                if (events && !done) {
                    const auto n = ::recv(c.sock, peek.data(), peek.size(), MSG_DONTWAIT);
                    done = n == 0 ||
                           (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR);
                    c.drained += n > 0 ? static_cast<std::size_t>(n) : 0;
                    done = done || c.drained > kLingerBytes;
                }
                if (done) {
                    close(c);
                } else {
                    still.push_back(std::move(c));
                }
                continue;
            }
            if (c.reading_body) {
                const Progress p = events ? read_body(c, peek) : Progress::Waiting;
                if (p == Progress::Gone) {
                    close(c);
                } else if (p == Progress::Ready) {
                    ready.push_back(std::move(c));
                } else if (now >= c.deadline) {
                    reply_directly(c.sock, 408, "Request Timeout",
                                   "the request body did not arrive within " +
                                       seconds_text(limits_.read_timeout) + " s");
                    close(c);
                } else {
                    still.push_back(std::move(c));
                }
                continue;
            }
            ssize_t n = -1;
            bool gone = false;
            if (events || now >= c.deadline) {
                n = ::recv(c.sock, peek.data(), peek.size(), MSG_PEEK | MSG_DONTWAIT);
                gone =
                    n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR);
            }
            const std::size_t head_end =
                n > 0 ? std::string_view(peek.data(), n).find("\r\n\r\n") : std::string_view::npos;
            // A whole head: its body, if any, is read here too, before a
            // worker is given the request.
            Progress body = Progress::Ready;
            if (!gone && head_end != std::string_view::npos) {
                body = start_body(c, std::string_view(peek.data(), head_end + 4));
                if (body == Progress::Waiting) body = read_body(c, peek);
            }
            const bool head = n > 0 && (head_end != std::string_view::npos ||
                                        static_cast<std::size_t>(n) >= peek.size() ||
                                        (events & (POLLRDHUP | POLLHUP | POLLERR)));
            if (gone || body == Progress::Gone) {
                close(c);
            } else if (body == Progress::Waiting) {
                still.push_back(std::move(c));
            } else if (head) {
                ready.push_back(std::move(c));
            } else if (now >= c.deadline) {
                // Silence on a kept-alive or fresh connection is no request;
                // half a head is one that came too slowly.
                if (n > 0)
                    reply_directly(c.sock, 408, "Request Timeout",
                                   "the request head did not arrive within " +
                                       seconds_text(limits_.head_timeout) + " s");
                close(c);
            } else {
                still.push_back(std::move(c));
            }
        }
        waiting = std::move(still);
        if (!ready.empty()) {
            {
                std::lock_guard<std::mutex> lock(mutex_);
                for (auto& c : ready) ready_.push_back(std::move(c));
            }
            ready_changed_.notify_all();
        }
    }
    for (auto& c : waiting) close(c);
}

void ConnectionServer::work() {
    for (;;) {
        Connection c;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            ready_changed_.wait(lock, [this] { return stopping_ || !ready_.empty(); });
            if (stopping_) return;
            c = std::move(ready_.front());
            ready_.pop_front();
        }
        serve(std::move(c));
    }
}

ConnectionServer::Progress ConnectionServer::start_body(Connection& c, std::string_view head) {
    bool chunked = false;
    std::vector<std::string_view> lengths;
    for (const HeaderLine& h : header_lines(head)) {
        if (equals_ignoring_case(h.name, "transfer-encoding") &&
            contains_ignoring_case(h.value, "chunked"))
            chunked = true;
        if (equals_ignoring_case(h.name, "content-length")) lengths.push_back(h.value);
    }
    const std::size_t largest = std::min(payload_max_length_, kLargestBody);
    std::size_t length = 0;
    if (!chunked) {
        // No body, or one a worker refuses unread (a length that is not one
        // number, or too large).
        if (lengths.size() != 1 || lengths[0].empty() || lengths[0].size() > 19 ||
            lengths[0].find_first_not_of("0123456789") != std::string_view::npos)
            return Progress::Ready;
        length = std::stoull(std::string(lengths[0]));
        if (length == 0 || length > largest) return Progress::Ready;
    }
    // The head is taken off the socket: from here on the room reads the
    // request, and the worker gets it from c.received.
    std::string received(head.size(), '\0');
    for (std::size_t got = 0; got < received.size();) {
        const auto n = ::recv(c.sock, received.data() + got, received.size() - got, MSG_DONTWAIT);
        if (n > 0) {
            got += static_cast<std::size_t>(n);
        } else if (n < 0 && errno == EINTR) {
            continue;
        } else {
            return Progress::Gone;  // it was peeked: only a broken connection loses it
        }
    }
    // A client that waits for "100 Continue" before it sends the body gets
    // it now; the header goes, so that the worker does not send another.
    for (const HeaderLine& h : header_lines(received)) {
        if (!equals_ignoring_case(h.name, "expect") ||
            !equals_ignoring_case(h.value, "100-continue"))
            continue;
        received.erase(h.begin, h.end + 2 - h.begin);
        const char reply[] = "HTTP/1.1 100 Continue\r\n\r\n";
        [[maybe_unused]] const auto sent =
            ::send(c.sock, reply, sizeof reply - 1, MSG_DONTWAIT | MSG_NOSIGNAL);
        break;
    }
    c.received = std::move(received);
    c.reading_body = true;
    c.chunked = chunked;
    c.body_end = c.received.size() + length;
    c.chunk_at = c.received.size();
    c.chunk_left = 0;
    c.chunk_phase = 0;
    c.deadline = after(limits_.read_timeout);
    return Progress::Waiting;
}

ConnectionServer::Progress ConnectionServer::read_body(Connection& c, std::vector<char>& scratch) {
    const std::size_t largest = std::min(payload_max_length_, kLargestBody);
    for (;;) {
        std::size_t want = scratch.size();
        if (!c.chunked) want = std::min(want, c.body_end - c.received.size());
        if (want == 0) return Progress::Ready;
        // Chunked bodies are peeked first: what follows the last chunk
        // belongs to the next request and stays on the socket.
        const auto n =
            ::recv(c.sock, scratch.data(), want, MSG_DONTWAIT | (c.chunked ? MSG_PEEK : 0));
        if (n == 0) return Progress::Ready;  // all the client sends: the worker answers it
        if (n < 0) {
            if (errno == EINTR) continue;
            if (errno == EAGAIN || errno == EWOULDBLOCK) return Progress::Waiting;
            return Progress::Gone;
        }
        if (!c.chunked) {
            c.received.append(scratch.data(), static_cast<std::size_t>(n));
            if (c.received.size() >= c.body_end) return Progress::Ready;
            continue;
        }
        const std::size_t before = c.received.size();
        c.received.append(scratch.data(), static_cast<std::size_t>(n));
        const ChunkScan scan = scan_chunks(c, largest);
        if (scan.done) c.received.resize(scan.end);
        const std::size_t take = c.received.size() - before;
        for (std::size_t got = 0; got < take;) {
            const auto m = ::recv(c.sock, scratch.data(), take - got, MSG_DONTWAIT);
            if (m > 0) {
                got += static_cast<std::size_t>(m);
            } else if (m < 0 && errno == EINTR) {
                continue;
            } else {
                return Progress::Gone;
            }
        }
        // Past the limit, or not chunked framing: the worker refuses it.
        if (scan.done || scan.bad || c.received.size() > largest + kChunkFraming)
            return Progress::Ready;
    }
}

void ConnectionServer::serve(Connection c) {
    RequestStream stream(c.sock, c.remote_ip, c.remote_port, c.local_ip, c.local_port, limits_,
                         std::move(c.received));
    c.received.clear();
    c.reading_body = false;
    const bool last = ++c.served >= keep_alive_max_count_ || svr_sock_ == INVALID_SOCKET;
    bool closed = false;
    const bool ok = process_request(stream, last, closed, nullptr);
    if (ok && !last && !closed && !stream.reply_closes()) {
        c.deadline = after(limits_.head_timeout);
    } else {
        ::shutdown(c.sock, SHUT_WR);
        c.draining = true;
        c.deadline = Clock::now() + kLinger;
    }
    to_room(std::move(c));
}

}  // namespace modsynth::app
