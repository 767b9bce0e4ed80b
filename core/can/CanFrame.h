#pragma once

#include <array>
#include <cstdint>
#include <span>

namespace stellwerk::can {

// One frame on a CAN bus, whatever protocol it belongs to: a 29-bit (extended) or 11-bit (standard)
// identifier, the data length code and up to eight data bytes. The one frame type every codec, transport
// and monitor shares. The DLC is kept as received (a broken sender may claim more than 8); isWellFormed()
// says whether the frame could be on a bus at all.
struct CanFrame {
    static constexpr std::uint32_t ExtendedIdMask = 0x1FFFFFFF;
    static constexpr std::uint32_t StandardIdMask = 0x7FF;
    // Size of the network form the CS2 UDP/TCP gateways carry (extended frames only).
    static constexpr std::size_t NetworkSize = 13;

    std::uint32_t id = 0;
    std::uint8_t dlc = 0;
    std::array<std::uint8_t, 8> data{};
    // 29-bit identifier (CAN 2.0B); false for an 11-bit one (CAN 2.0A).
    bool extended = true;

    // A standard (11-bit) frame with the given payload (at most 8 bytes are taken).
    static CanFrame standard(std::uint32_t id, std::span<const std::uint8_t> payload);
    // An extended (29-bit) frame with the given payload (at most 8 bytes are taken).
    static CanFrame extendedFrame(std::uint32_t id, std::span<const std::uint8_t> payload);

    constexpr std::uint32_t idMask() const { return extended ? ExtendedIdMask : StandardIdMask; }
    // Number of valid payload bytes: the DLC, clipped to the eight bytes a frame can hold.
    constexpr std::size_t size() const { return dlc > 8 ? 8 : dlc; }
    constexpr std::span<const std::uint8_t> payload() const { return {data.data(), size()}; }
    // The identifier fits its width and the DLC is at most 8.
    constexpr bool isWellFormed() const { return dlc <= 8 && (id & ~idMask()) == 0; }

    // The 13-byte form of the CS2 UDP/TCP gateways: id (big endian), DLC, data padded with zeros. It has
    // no room for the frame format, so it carries extended frames only: check fitsNetworkForm() first (the
    // transports refuse a standard frame with an error).
    constexpr bool fitsNetworkForm() const { return extended; }
    std::array<std::uint8_t, NetworkSize> toNetwork() const;
    // Reads the 13-byte form (always an extended frame). The result keeps whatever DLC and id bits the
    // bytes carry, so that a decoder can report them; use isWellFormed() for a quick check.
    static CanFrame fromNetwork(std::span<const std::uint8_t, NetworkSize> bytes);

    friend constexpr bool operator==(const CanFrame& a, const CanFrame& b) {
        if (a.id != b.id || a.dlc != b.dlc || a.extended != b.extended)
            return false;
        for (std::size_t i = 0; i < a.size(); ++i)
            if (a.data[i] != b.data[i])
                return false;
        return true;
    }
};

} // namespace stellwerk::can
