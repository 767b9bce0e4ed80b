#pragma once

#include "cs2/Header.h"
#include "cs2config/ConfigStreamKeys.h"
#include "cs2config/ConfigStreamRequest.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace stellwerk::cs2config {

// How a stream goes out: to one requester (DLC 6 header, the requester's hash) or as the broadcast
// "configuration changed" (DLC 7 header with one more byte, the sender's hash).
struct StreamAddress {
    static constexpr std::uint8_t DefaultBroadcastValue = 0x7B; // seen from real stations

    std::uint16_t hash = 0;
    std::optional<std::uint8_t> broadcastValue;

    static StreamAddress reply(std::uint16_t requesterHash) { return {requesterHash, std::nullopt}; }
    static StreamAddress broadcast(std::uint16_t senderHash, std::uint8_t value = DefaultBroadcastValue) {
        return {senderHash, value};
    }
};

// The bytes a stream carries for a file in the given format (before the frames' zero padding).
std::vector<std::uint8_t> streamPayload(std::string_view contents, StreamFormat format);

// Header and data frames for payload bytes as they are (the receiver's streamBytes, or test data).
std::vector<can::CanFrame> payloadFrames(std::span<const std::uint8_t> payload, StreamAddress address);

// The frames a CS2 sends for a file (document 7.2): the header with the payload length and the
// CRC over the zero-padded payload, then DLC-8 data frames; priority 0, no response bit.
std::vector<can::CanFrame> streamFrames(std::string_view contents, StreamFormat format,
                                        StreamAddress address);

// The station's whole answer to a request: its acknowledgement (the request frames with the
// response bit) and the stream in the key's format (compressed for unknown keys).
std::vector<can::CanFrame> answerFrames(const ConfigRequest& request, std::string_view contents,
                                        std::uint16_t requesterHash);

// The format a station uses for a key: from the document's table, compressed when unknown.
StreamFormat streamFormatForKey(std::string_view key);

} // namespace stellwerk::cs2config
