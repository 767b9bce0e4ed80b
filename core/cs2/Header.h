#pragma once

#include "can/CanFrame.h"

#include <cstdint>

namespace stellwerk::cs2 {

// The CS2 codec speaks in the bus's frames.
using can::CanFrame;

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

// The CS2 header in a 29-bit CAN identifier (document 1.2): priority (bits 25-28), command (17-24),
// response bit (16) and hash (0-15).
constexpr std::uint32_t makeId(std::uint8_t prio, std::uint8_t command, bool response, std::uint16_t hash) {
    return (std::uint32_t(prio & 0x0F) << 25) | (std::uint32_t(command) << 17) |
           (std::uint32_t(response ? 1 : 0) << 16) | hash;
}
constexpr std::uint8_t prio(const CanFrame& frame) {
    return std::uint8_t((frame.id >> 25) & 0x0F);
}
constexpr std::uint8_t command(const CanFrame& frame) {
    return std::uint8_t((frame.id >> 17) & 0xFF);
}
constexpr bool isResponse(const CanFrame& frame) {
    return (frame.id >> 16) & 1;
}
constexpr std::uint16_t hash(const CanFrame& frame) {
    return std::uint16_t(frame.id & 0xFFFF);
}

} // namespace stellwerk::cs2
