#pragma once

#include "cs2/Messages.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>

namespace stellwerk::station {

// What an acknowledgement must echo to answer a command (field notes: "match a response by command,
// response bit and payload, not by hash alone"): the command, the system sub-command and the fields
// the document says come back unchanged (Loc-ID, device UID, function, channel, file key, ...).
struct AckKey {
    std::uint8_t command = 0;
    std::uint8_t subcommand = 0;
    std::uint32_t subject = 0; // Loc-ID, device UID, feedback device + contact, first 4 key bytes
    std::uint32_t detail = 0;  // function number, channel, position, CV, last 4 key bytes, index

    friend bool operator==(const AckKey&, const AckKey&) = default;
};

struct AckKeyHash {
    std::size_t operator()(const AckKey& key) const {
        const std::uint64_t high = (std::uint64_t(key.command) << 8 | key.subcommand) * 0x9E3779B97F4A7C15ull;
        return std::hash<std::uint64_t>{}(high ^ (std::uint64_t(key.subject) << 32 | key.detail));
    }
};

// The key of a command or of its answer; both give the same key. nullopt for messages that are not
// answered one-to-one (ping, streams, status-data packets, unknown commands).
std::optional<AckKey> ackKeyOf(const cs2::Message& message);

// True for an answer that says the command was not carried out: a refused configuration value, a
// measurement channel the device does not have, a CV that could not be read or written, a failed
// mfx verify.
bool isRejection(const cs2::Message& answer);

} // namespace stellwerk::station
