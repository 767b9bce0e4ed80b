#pragma once

#include "cs2/Hash.h"
#include "cs2/Header.h"

#include <array>
#include <cstdint>
#include <optional>

namespace stellwerk::station {

// Who we are on the bus: our UID and the hash derived from it (document 1.2.4), kept free of
// collisions: a command from another sender with our hash makes us pick a new one.
class StationIdentity {
public:
    // A random UID when none is given (in the range the document leaves to PC software).
    explicit StationIdentity(std::optional<std::uint32_t> uid = std::nullopt);

    std::uint32_t uid() const { return uid_; }
    std::uint16_t hash() const { return guard_.hash(); }

    // Writes our current hash into a frame we are about to send and remembers the frame, so that a
    // gateway that echoes our own frames back does not look like a collision.
    can::CanFrame stamp(can::CanFrame frame);
    // Looks at a received frame; returns the new hash when it showed another sender using ours.
    std::optional<std::uint16_t> observe(const can::CanFrame& frame);

private:
    static constexpr std::size_t EchoMemory = 32;

    bool isOwnEcho(const can::CanFrame& frame) const;

    std::uint32_t uid_;
    cs2::HashGuard guard_;
    std::array<can::CanFrame, EchoMemory> sent_{};
    std::size_t sentCount_ = 0;
};

} // namespace stellwerk::station
