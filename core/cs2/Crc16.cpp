#include "cs2/Crc16.h"

#include <array>

namespace stellwerk::cs2 {
namespace {

constexpr std::array<std::uint16_t, 256> makeTable() {
    std::array<std::uint16_t, 256> table{};
    for (unsigned byte = 0; byte < 256; ++byte) {
        std::uint16_t acc = std::uint16_t(byte << 8);
        for (int bit = 0; bit < 8; ++bit)
            acc = (acc & 0x8000) ? std::uint16_t((acc << 1) ^ 0x1021) : std::uint16_t(acc << 1);
        table[byte] = acc;
    }
    return table;
}

constexpr auto Table = makeTable();

} // namespace

std::uint16_t crc16(std::span<const std::uint8_t> bytes, std::uint16_t crc) {
    for (std::uint8_t byte : bytes)
        crc = std::uint16_t((crc << 8) ^ Table[((crc >> 8) ^ byte) & 0xFF]);
    return crc;
}

} // namespace stellwerk::cs2
