#pragma once

#include "ro/Messages.h"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace stellwerk::ro {

// RO data is little endian (004 §2.2: "Begonnen wird mit den niederwertigen Bytes"), unlike the CS2's big
// endian: these two helpers are the only place that byte order is written down.
std::uint32_t readLittleEndian(std::span<const std::uint8_t> bytes);
void writeLittleEndian(std::span<std::uint8_t> bytes, std::uint32_t value);

// The byte-addressed register memory of an RO module (004 §2.2: "Eine Adresse weist auf 8 Bits"): 64 KiB,
// accessed 8, 16 or 32 bits wide as one little-endian block from the address on. A bit access, which the
// document leaves undefined (notes R6), takes the address as a bit number: byte address >> 3, bit
// address & 7. An access that would run past 0xFFFF is refused (nullopt / false), never wrapped (R13).
class RegisterFile {
public:
    static constexpr std::size_t Size = 0x10000;

    RegisterFile();

    std::optional<std::uint32_t> read(std::uint16_t address, Width width) const;
    // Writes the low bits of `value` that the width covers; false when the access runs past the end.
    bool write(std::uint16_t address, Width width, std::uint32_t value);

    std::uint8_t byteAt(std::uint16_t address) const { return memory_[address]; }

private:
    std::vector<std::uint8_t> memory_;
};

} // namespace stellwerk::ro
