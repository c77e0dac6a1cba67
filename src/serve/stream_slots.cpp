#include "stream_slots.h"

namespace modsynth::app {

std::shared_ptr<void> StreamSlots::acquire(const std::string& client) {
    std::lock_guard<std::mutex> lock(state_->mutex);
    std::size_t& mine = state_->by_client[client];
    if (state_->used >= total_ || mine >= per_client_) {
        if (mine == 0) state_->by_client.erase(client);
        return nullptr;
    }
    ++mine;
    ++state_->used;
    // The pointer only marks the handle as held; the deleter frees the slot.
    return std::shared_ptr<void>(state_.get(), [state = state_, client](void*) {
        std::lock_guard<std::mutex> lock(state->mutex);
        --state->used;
        if (--state->by_client[client] == 0) state->by_client.erase(client);
    });
}

}  // namespace modsynth::app
