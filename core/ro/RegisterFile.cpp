#include "ro/RegisterFile.h"

namespace stellwerk::ro {
namespace {

bool fits(std::uint16_t address, Width width) {
    return width != Width::None && std::size_t(address) + byteCount(width) <= RegisterFile::Size;
}

} // namespace

std::uint32_t readLittleEndian(std::span<const std::uint8_t> bytes) {
    std::uint32_t value = 0;
    for (std::size_t i = bytes.size(); i-- > 0;)
        value = (value << 8) | bytes[i];
    return value;
}

void writeLittleEndian(std::span<std::uint8_t> bytes, std::uint32_t value) {
    for (std::uint8_t& byte : bytes) {
        byte = std::uint8_t(value & 0xFF);
        value >>= 8;
    }
}

RegisterFile::RegisterFile() : memory_(Size, 0) {}

std::optional<std::uint32_t> RegisterFile::read(std::uint16_t address, Width width) const {
    if (width == Width::Bit)
        return (memory_[address >> 3] >> (address & 7)) & 1u;
    if (!fits(address, width))
        return std::nullopt;
    return readLittleEndian(std::span(memory_).subspan(address, byteCount(width)));
}

bool RegisterFile::write(std::uint16_t address, Width width, std::uint32_t value) {
    if (width == Width::Bit) {
        const std::uint8_t mask = std::uint8_t(1u << (address & 7));
        std::uint8_t& byte = memory_[address >> 3];
        byte = std::uint8_t((value & 1) ? byte | mask : byte & ~mask);
        return true;
    }
    if (!fits(address, width))
        return false;
    writeLittleEndian(std::span(memory_).subspan(address, byteCount(width)), value);
    return true;
}

} // namespace stellwerk::ro
