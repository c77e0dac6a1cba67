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

bool contains_ignoring_case(const std::string& text, const std::string& lower_needle) {
    return std::search(text.begin(), text.end(), lower_needle.begin(), lower_needle.end(),
                       [](char a, char b) {
                           return std::tolower(static_cast<unsigned char>(a)) == b;
                       }) != text.end();
}

/// One request on a connection whose head has come: reads bounded by the
/// request's deadline, writes by the write timeout.
class RequestStream : public httplib::Stream {
public:
    RequestStream(int sock, const std::string& remote_ip, int remote_port,
                  const std::string& local_ip, int local_port, const ConnectionLimits& limits)
        : sock_(sock),
          remote_ip_(remote_ip),
          local_ip_(local_ip),
          remote_port_(remote_port),
          local_port_(local_port),
          read_deadline_(after(limits.read_timeout)),
          write_timeout_ms_(static_cast<int>(limits.write_timeout * 1000)) {}

    bool is_readable() const override {
        return wait_for(sock_, POLLIN, millis_until(read_deadline_));
    }

    bool is_writable() const override {
        if (!wait_for(sock_, POLLOUT, write_timeout_ms_)) return false;
        // A client that hung up reads as end of file.
        char c;
        const auto n = ::recv(sock_, &c, 1, MSG_PEEK | MSG_DONTWAIT);
        return n > 0 || (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK));
    }

    ssize_t read(char* ptr, std::size_t size) override {
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
    std::string head_;  ///< the start of what was written: the reply's head
};

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
            ssize_t n = -1;
            bool gone = false;
            if (events || now >= c.deadline) {
                n = ::recv(c.sock, peek.data(), peek.size(), MSG_PEEK | MSG_DONTWAIT);
                gone =
                    n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR);
            }
            const bool head = n > 0 && (std::string_view(peek.data(), n).find("\r\n\r\n") !=
                                            std::string_view::npos ||
                                        static_cast<std::size_t>(n) >= peek.size() ||
                                        (events & (POLLRDHUP | POLLHUP | POLLERR)));
            if (gone) {
                close(c);
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

void ConnectionServer::serve(Connection c) {
    RequestStream stream(c.sock, c.remote_ip, c.remote_port, c.local_ip, c.local_port, limits_);
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
