#pragma once
// Requests that hold a server worker for long (progress streams, long
// polls) take a slot each; one client may hold only a few, and all clients
// together fewer than there are workers, so that ordinary requests always
// find a free one.
#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace modsynth::app {

class StreamSlots {
public:
    StreamSlots(std::size_t total, std::size_t per_client)
        : state_(std::make_shared<State>()), total_(total), per_client_(per_client) {}

    /// A slot for `client` (its address), freed when the last copy of the
    /// handle goes; nothing when the client or the server is at its cap.
    std::shared_ptr<void> acquire(const std::string& client);

    std::size_t total() const { return total_; }
    std::size_t per_client() const { return per_client_; }

private:
    // Shared with the handles, which may outlive this object in a reply
    // still being written.
    struct State {
        std::mutex mutex;
        std::size_t used = 0;
        std::map<std::string, std::size_t> by_client;
    };
    std::shared_ptr<State> state_;
    std::size_t total_;
    std::size_t per_client_;
};

}  // namespace modsynth::app
