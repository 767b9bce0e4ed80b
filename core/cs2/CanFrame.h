#pragma once

#include <array>
#include <cstdint>
#include <span>

namespace stellwerk::cs2 {

// Command numbers of the CS2 protocol (document chapter 1.4), as carried in CAN-id bits 17-24.
enum class Command : std::uint8_t {
    System = 0x00,
    LocoDiscovery = 0x01,
    MfxBind = 0x02,
    MfxVerify = 0x03,
    LocoSpeed = 0x04,
    LocoDirection = 0x05,
    LocoFunction = 0x06,
    ConfigRead = 0x07,
    ConfigWrite = 0x08,
    AccessorySwitch = 0x0B,
    AccessoryConfig = 0x0C,
    S88Poll = 0x10,
    S88Event = 0x11,
    Sx1Event = 0x12,
    Ping = 0x18,
    UpdateOffer = 0x19,
    ReadConfigData = 0x1A,
    BootloaderCan = 0x1B,
    BootloaderTrack = 0x1C,
    StatusDataConfig = 0x1D,
    ConfigDataRequest = 0x20,
    ConfigDataStream = 0x21,
    Connect6021Stream = 0x22,
    AutomationSwitch = 0x30,
};

// One CAN frame of the CS2 bus: 29-bit identifier, data length code and up to eight data bytes.
// The DLC is kept as received (a broken sender may claim more than 8); the decoder rejects that.
struct CanFrame {
    static constexpr std::uint32_t IdMask = 0x1FFFFFFF;
    static constexpr std::size_t NetworkSize = 13;

    std::uint32_t id = 0;
    std::uint8_t dlc = 0;
    std::array<std::uint8_t, 8> data{};

    static constexpr std::uint32_t makeId(std::uint8_t prio, std::uint8_t command, bool response,
                                          std::uint16_t hash) {
        return (std::uint32_t(prio & 0x0F) << 25) | (std::uint32_t(command) << 17) |
               (std::uint32_t(response ? 1 : 0) << 16) | hash;
    }

    constexpr std::uint8_t prio() const { return std::uint8_t((id >> 25) & 0x0F); }
    constexpr std::uint8_t command() const { return std::uint8_t((id >> 17) & 0xFF); }
    constexpr bool isResponse() const { return (id >> 16) & 1; }
    constexpr std::uint16_t hash() const { return std::uint16_t(id & 0xFFFF); }
    // Number of valid payload bytes: the DLC, clipped to the eight bytes a frame can hold.
    constexpr std::size_t size() const { return dlc > 8 ? 8 : dlc; }
    constexpr std::span<const std::uint8_t> payload() const { return {data.data(), size()}; }

    // The 13-byte form used by the UDP/TCP gateways: id (big endian), DLC, data padded with zeros.
    std::array<std::uint8_t, NetworkSize> toNetwork() const;
    // Reads the 13-byte form. The result keeps whatever DLC and id bits the bytes carry, so that
    // the decoder can report them; use isWellFormed() for a quick check.
    static CanFrame fromNetwork(std::span<const std::uint8_t, NetworkSize> bytes);

    constexpr bool isWellFormed() const { return dlc <= 8 && (id & ~IdMask) == 0; }

    friend constexpr bool operator==(const CanFrame& a, const CanFrame& b) {
        if (a.id != b.id || a.dlc != b.dlc)
            return false;
        for (std::size_t i = 0; i < a.size(); ++i)
            if (a.data[i] != b.data[i])
                return false;
        return true;
    }
};

} // namespace stellwerk::cs2
