#pragma once

#include <cstdint>
#include <span>

namespace stellwerk::cs2 {

// CRC-16 of the config-data stream (document 7.2): polynomial 0x1021, start 0xFFFF, no reflection,
// no final XOR ("CCITT-FALSE"). Feed it every received data byte, padding included.
std::uint16_t crc16(std::span<const std::uint8_t> bytes, std::uint16_t crc = 0xFFFF);

} // namespace stellwerk::cs2
