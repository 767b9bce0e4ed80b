#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

namespace stellwerk::z21 {

// A Z21 datagram cut into its packets (spec 1.2.1 and 1.3): each packet is DataLen (16 bits, little
// endian, counting itself), Header (16 bits, little endian) and DataLen - 4 bytes of data; one UDP
// datagram may carry several. X-bus packets (header 0x40, 1.2.2) end with an XOR byte over their X-header
// and data bytes.

inline constexpr std::uint16_t XBusHeader = 0x40;
// The most a datagram carries in one Ethernet frame (1.3): 1500 - 20 - 8 bytes.
inline constexpr std::size_t MaxDatagramSize = 1472;

// One packet as framed; data points into the datagram.
struct Packet {
    std::size_t offset = 0;
    std::uint16_t header = 0;
    std::span<const std::uint8_t> data;
};

// What is wrong with a packet: a DataLen below 4 or beyond the datagram's end (framing stops there), or
// a known command whose length is not the specification's (the next packet is still read); for a
// client reading replies, a packet that is none of the replies it knows.
enum class PacketProblem : std::uint8_t { LengthBelowFour, Truncated, WrongLength, NotAReply };

struct PacketError {
    std::size_t offset = 0; // where the packet starts in the datagram
    PacketProblem problem = PacketProblem::Truncated;
    std::uint16_t header = 0;
    std::string detail;
};

// The packets of a datagram in order, and the framing error that ended the reading early, if any.
struct Framing {
    std::vector<Packet> packets;
    std::vector<PacketError> errors;
};
Framing frameDatagram(std::span<const std::uint8_t> datagram);

// The XOR of bytes (1.2.2's check byte when taken over X-header and data).
std::uint8_t xorOf(std::span<const std::uint8_t> bytes);

// Writes one packet: the header and data, then DataLen in front when finished.
class PacketWriter {
public:
    explicit PacketWriter(std::uint16_t header);
    PacketWriter& byte(std::uint8_t value);
    PacketWriter& bytes(std::initializer_list<std::uint8_t> values);
    PacketWriter& littleEndian16(std::uint16_t value);
    PacketWriter& littleEndian32(std::uint32_t value);
    PacketWriter& bigEndian16(std::uint16_t value);
    std::vector<std::uint8_t> finish();
    // An X-bus packet: the XOR byte over everything written after the header is appended first.
    std::vector<std::uint8_t> finishXBus();

private:
    std::vector<std::uint8_t> bytes_;
};

// Loco address <-> Adr_MSB, Adr_LSB (4.1): the two top bits of Adr_MSB are ignored when reading and set
// for addresses from 128 on when writing.
std::uint16_t locoAddress(std::uint8_t msb, std::uint8_t lsb);
std::uint8_t locoAddressMsb(std::uint16_t address);

std::uint16_t readLittleEndian16(std::span<const std::uint8_t> bytes);
std::uint32_t readLittleEndian32(std::span<const std::uint8_t> bytes);
std::uint16_t readBigEndian16(std::span<const std::uint8_t> bytes);

} // namespace stellwerk::z21
