#include "z21/Packet.h"

namespace stellwerk::z21 {

namespace {

PacketError framingError(std::size_t offset, PacketProblem problem, std::string detail) {
    return {offset, problem, 0, std::move(detail)};
}

} // namespace

Framing frameDatagram(std::span<const std::uint8_t> datagram) {
    Framing framing;
    std::size_t offset = 0;
    while (offset < datagram.size()) {
        const auto rest = datagram.subspan(offset);
        if (rest.size() < 4) {
            framing.errors.push_back(
                framingError(offset, PacketProblem::Truncated,
                             std::to_string(rest.size()) + " bytes after the last packet"));
            break;
        }
        const std::uint16_t length = readLittleEndian16(rest);
        if (length < 4) {
            framing.errors.push_back(framingError(offset, PacketProblem::LengthBelowFour,
                                                  "DataLen " + std::to_string(length) + " is below 4"));
            break;
        }
        if (length > rest.size()) {
            framing.errors.push_back(framingError(offset, PacketProblem::Truncated,
                                                  "DataLen " + std::to_string(length) + ", but only " +
                                                      std::to_string(rest.size()) + " bytes left"));
            break;
        }
        framing.packets.push_back(
            {offset, readLittleEndian16(rest.subspan(2)), rest.subspan(4, length - 4u)});
        offset += length;
    }
    return framing;
}

std::uint8_t xorOf(std::span<const std::uint8_t> bytes) {
    std::uint8_t value = 0;
    for (const std::uint8_t byte : bytes)
        value ^= byte;
    return value;
}

PacketWriter::PacketWriter(std::uint16_t header) : bytes_{0, 0} {
    littleEndian16(header);
}

PacketWriter& PacketWriter::byte(std::uint8_t value) {
    bytes_.push_back(value);
    return *this;
}

PacketWriter& PacketWriter::bytes(std::initializer_list<std::uint8_t> values) {
    bytes_.insert(bytes_.end(), values);
    return *this;
}

PacketWriter& PacketWriter::littleEndian16(std::uint16_t value) {
    return bytes({std::uint8_t(value & 0xFF), std::uint8_t(value >> 8)});
}

PacketWriter& PacketWriter::littleEndian32(std::uint32_t value) {
    littleEndian16(std::uint16_t(value & 0xFFFF));
    return littleEndian16(std::uint16_t(value >> 16));
}

PacketWriter& PacketWriter::bigEndian16(std::uint16_t value) {
    return bytes({std::uint8_t(value >> 8), std::uint8_t(value & 0xFF)});
}

std::vector<std::uint8_t> PacketWriter::finish() {
    const auto length = std::uint16_t(bytes_.size());
    bytes_[0] = std::uint8_t(length & 0xFF);
    bytes_[1] = std::uint8_t(length >> 8);
    return std::move(bytes_);
}

std::vector<std::uint8_t> PacketWriter::finishXBus() {
    byte(xorOf(std::span(bytes_).subspan(4)));
    return finish();
}

std::uint16_t locoAddress(std::uint8_t msb, std::uint8_t lsb) {
    return std::uint16_t(((msb & 0x3Fu) << 8) | lsb);
}

std::uint8_t locoAddressMsb(std::uint16_t address) {
    const auto msb = std::uint8_t((address >> 8) & 0x3F);
    return address >= 128 ? std::uint8_t(msb | 0xC0) : msb;
}

std::uint16_t readLittleEndian16(std::span<const std::uint8_t> bytes) {
    return std::uint16_t(bytes[0] | (bytes[1] << 8));
}

std::uint32_t readLittleEndian32(std::span<const std::uint8_t> bytes) {
    return readLittleEndian16(bytes) | (std::uint32_t(readLittleEndian16(bytes.subspan(2))) << 16);
}

std::uint16_t readBigEndian16(std::span<const std::uint8_t> bytes) {
    return std::uint16_t((bytes[0] << 8) | bytes[1]);
}

} // namespace stellwerk::z21
