#pragma once
// An HTTP server whose connections cost a worker only while a request is
// being answered. A connection waits for its next request head, and then
// for the request's body, in one polling thread, not in a worker, so
// clients that send slowly or keep idle connections open cannot take every
// worker; each head and each body must arrive within a deadline, and
// closing connections are drained there too.
//
// Include it last: <httplib.h> pulls in <resolv.h>, whose `_res` macro
// breaks Eigen's headers.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include <httplib.h>

namespace modsynth::app {

struct ConnectionLimits {
    std::size_t workers = 16;           ///< requests answered at once
    std::size_t max_connections = 256;  ///< open at once; more are answered 429 and closed
    double head_timeout =
        5.0;  ///< seconds for a request head, from the connection or the last reply
    double read_timeout =
        10.0;  ///< seconds for the rest of a request (its body) once its head came
    double write_timeout = 10.0;  ///< seconds a client may leave one write of a reply waiting
};

class ConnectionServer : public httplib::Server {
public:
    explicit ConnectionServer(const ConnectionLimits& limits);
    ~ConnectionServer() override;
    ConnectionServer(const ConnectionServer&) = delete;
    ConnectionServer& operator=(const ConnectionServer&) = delete;

    const ConnectionLimits& limits() const { return limits_; }

    /// httplib's, with a listen backlog that takes a burst of connections:
    /// its own backlog of 5 overflows when dozens connect at once, and the
    /// kernel then answers with SYN cookies, a failed one of which resets a
    /// connection the client already thinks open.
    bool listen_after_bind();

private:
    using Clock = std::chrono::steady_clock;
    struct Connection {
        int sock = -1;
        std::string remote_ip, local_ip;
        int remote_port = 0, local_port = 0;
        std::size_t served = 0;
        bool draining = false;  ///< replied and closing: what the client still sends is dropped
        std::size_t drained = 0;
        Clock::time_point deadline;
        /// The request read so far, its head first, once its head has come
        /// and it has a body: the worker reads this before the socket.
        std::string received;
        bool reading_body = false;
        std::size_t body_end = 0;  ///< received.size() once a Content-Length body is in
        bool chunked = false;
        std::size_t chunk_at = 0;    ///< chunked: where the framing is parsed up to
        std::size_t chunk_left = 0;  ///< chunked: data and CRLF still to come of this chunk
        int chunk_phase = 0;         ///< chunked: 0 size line, 1 data, 2 trailers
    };
    enum class Progress { Ready, Waiting, Gone };

    bool process_and_close_socket(socket_t sock) override;
    void wait_room();
    /// A head has come (`head` bytes of it peeked): Ready when the request
    /// has no body the room should wait for, else its body is read from
    /// now on.
    Progress start_body(Connection& c, std::string_view head);
    /// Reads what has come of the body: Ready once it is all in (or cannot
    /// be, and the worker must say so), Gone when the connection broke.
    Progress read_body(Connection& c, std::vector<char>& scratch);

    void work();
    void serve(Connection c);
    void to_room(Connection c);
    void close(Connection& c);

    ConnectionLimits limits_;
    std::mutex mutex_;
    std::condition_variable ready_changed_;
    std::vector<Connection> incoming_;  ///< for the room to take
    std::deque<Connection> ready_;      ///< a head has come: for a worker
    bool stopping_ = false;
    std::atomic<std::size_t> open_{0};
    int wake_fd_ = -1;
    std::thread room_;
    std::vector<std::thread> workers_;
};

}  // namespace modsynth::app
