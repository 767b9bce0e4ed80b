#pragma once

#include "cs2/Header.h"

#include <bitset>
#include <cstdint>

namespace stellwerk::cs2 {

// The collision-resolving hash of the CAN id (document 1.2.4): UID high word XOR low word, with
// bits 7..9 forced to 0b110 so that no CS1 frame can look like a CS2 frame.
std::uint16_t hashFromUid(std::uint32_t uid);
// True when bits 7..9 carry the CS2 marker 0b110. MS2s and Gleisboxes send hashes without it.
constexpr bool hasCs2Marker(std::uint16_t hash) {
    return (hash & 0x0380) == 0x0300;
}

// Stream frames carry a 13-bit packet number in the hash field, with bits 7..9 masked out.
constexpr std::uint16_t packetNumberFromHash(std::uint16_t hash) {
    return std::uint16_t((hash & 0x7F) | ((hash >> 10) << 7));
}
constexpr std::uint16_t hashFromPacketNumber(std::uint16_t packet) {
    return std::uint16_t((((packet >> 7) & 0x3F) << 10) | 0x0300 | (packet & 0x7F));
}

// True for frames whose hash field is a packet number or a peer's stream id, not a sender's hash.
bool hashIsStreamPosition(const CanFrame& frame);

// Owns our own hash and applies the collision rule: another sender using it forces a new one,
// and the new one must differ from every hash seen on the bus so far.
class HashGuard {
public:
    explicit HashGuard(std::uint32_t uid);

    std::uint16_t hash() const { return hash_; }
    // Records the frame's hash; returns true when the frame shows another sender with our hash
    // (a command frame, not a response or stream frame, that we did not send ourselves).
    bool observe(const CanFrame& frame);
    // Picks a fresh hash that was never seen on the bus; returns it.
    std::uint16_t chooseNewHash();

private:
    std::uint32_t uid_;
    std::uint32_t attempt_ = 0;
    std::uint16_t hash_;
    std::bitset<65536> seen_;
};

} // namespace stellwerk::cs2
