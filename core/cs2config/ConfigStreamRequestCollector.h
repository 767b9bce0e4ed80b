#pragma once

#include "cs2/Messages.h"
#include "cs2config/ConfigStreamRequest.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::cs2config {

// A request seen on the bus: who asked (hash), and whether it was the station's acknowledgement.
struct CollectedConfigRequest {
    ConfigRequest request;
    std::uint16_t hash = 0;
    bool response = false;
};

// Recognises config-data requests in decoded traffic: a station (or the simulator) needs the key
// frame and its follow-up frames together. Requests and acknowledgements of several requesters may
// interleave; they are kept apart by hash and response bit. A lost follow-up frame makes the next
// request frame of that hash the follow-up: a caller with a timeout calls reset().
class ConfigRequestCollector {
public:
    // Returns the request once its last frame arrived; every other message gives nullopt.
    std::optional<CollectedConfigRequest> feed(const cs2::Message& message);

    // Requests still waiting for follow-up frames.
    std::size_t pendingCount() const { return pending_.size(); }
    // Forgets the requests still waiting for follow-up frames.
    void reset() { pending_.clear(); }

private:
    struct Pending {
        std::uint16_t hash;
        bool response;
        std::string key;
        std::string qualifier;
        std::uint8_t missing;
    };

    std::optional<CollectedConfigRequest> start(std::string key, std::uint16_t hash, bool response);
    std::optional<CollectedConfigRequest> add(std::vector<Pending>::iterator pending, std::string_view text);

    std::vector<Pending> pending_;
};

} // namespace stellwerk::cs2config
