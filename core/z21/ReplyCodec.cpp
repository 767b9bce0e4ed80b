#include "z21/ReplyCodec.h"

#include <optional>

namespace stellwerk::z21 {

namespace {

using Bytes = std::span<const std::uint8_t>;
using Read = std::optional<Reply>;

PacketError notAReply(const Packet& packet) {
    return {packet.offset, PacketProblem::NotAReply, packet.header,
            "no reply of " + std::to_string(packet.data.size() + 4) + " bytes with this header"};
}

Read readSystemState(Bytes d) {
    const auto at = [d](std::size_t offset) { return readLittleEndian16(d.subspan(offset)); };
    return SystemState{std::int16_t(at(0)),
                       std::int16_t(at(2)),
                       std::int16_t(at(4)),
                       std::int16_t(at(6)),
                       at(8),
                       at(10),
                       d[12],
                       d[13],
                       d[15]};
}

Read readLan(std::uint16_t header, Bytes d) {
    if (header == 0x10 && d.size() == 4)
        return SerialNumber{readLittleEndian32(d)};
    if (header == 0x18 && d.size() == 1)
        return FeatureCode{d[0]};
    if (header == 0x1A && d.size() == 8)
        return HardwareInfo{readLittleEndian32(d), readLittleEndian32(d.subspan(4))};
    if (header == 0x51 && d.size() == 4)
        return BroadcastFlags{readLittleEndian32(d)};
    if (header == 0x84 && d.size() == 16)
        return readSystemState(d);
    if ((header == 0x60 || header == 0x70) && d.size() == 3 && d[2] <= 1) {
        if (header == 0x60)
            return LocoMode{readBigEndian16(d), DecoderFormat(d[2])};
        return TurnoutMode{readBigEndian16(d), DecoderFormat(d[2])};
    }
    return std::nullopt;
}

// X 0x61 broadcasts (2.7 to 2.11), by DB0.
Read readBroadcast61(std::uint8_t db0) {
    switch (db0) {
    case 0x00:
        return TrackPowerOff{};
    case 0x01:
        return TrackPowerOn{};
    case 0x02:
        return ProgrammingMode{};
    case 0x08:
        return TrackShortCircuit{};
    case 0x82:
        return UnknownCommand{};
    default:
        return std::nullopt;
    }
}

Read readLocoInfo(Bytes x) {
    const auto mode = modeFromInfoCode(x[3] & 0x07);
    if (!mode)
        return std::nullopt;
    std::uint32_t functions = ((x[5] >> 4) & 1u) | ((x[5] & 0x0Fu) << 1) | (std::uint32_t(x[6]) << 5) |
                              (std::uint32_t(x[7]) << 13) | (std::uint32_t(x[8]) << 21);
    if (x.size() > 9)
        functions |= std::uint32_t(x[9] & 0x07) << 29;
    return LocoInfo{locoAddress(x[1], x[2]), (x[3] & 0x08) != 0, speedFromByte(*mode, x[4]), functions,
                    (x[5] & 0x40) != 0,      (x[5] & 0x20) != 0};
}

// x = X-header and data, without the XOR byte.
Read readX(Bytes x) {
    const std::size_t n = x.size();
    if (x[0] == 0x61 && n == 2)
        return readBroadcast61(x[1]);
    if (x[0] == 0x62 && n == 3 && x[1] == 0x22)
        return XStatusChanged{x[2]};
    if (x[0] == 0x63 && n == 4 && x[1] == 0x21)
        return XVersion{x[2], x[3]};
    if (x[0] == 0x81 && n == 2 && x[1] == 0x00)
        return Stopped{};
    if (x[0] == 0xF3 && n == 4 && x[1] == 0x0A)
        return FirmwareVersion{readBigEndian16(x.subspan(2))};
    if (x[0] == 0xEF && n >= 9)
        return readLocoInfo(x);
    if (x[0] == 0x43 && n == 4)
        return TurnoutInfo{readBigEndian16(x.subspan(1)), TurnoutPosition(x[3] & 0x03)};
    return std::nullopt;
}

} // namespace

Expected<Reply, PacketError> readReply(const Packet& packet) {
    Read read;
    if (packet.header != XBusHeader)
        read = readLan(packet.header, packet.data);
    else if (packet.data.size() >= 2)
        read = readX(packet.data.first(packet.data.size() - 1));
    if (!read)
        return notAReply(packet);
    return *read;
}

DatagramReplies readReplies(std::span<const std::uint8_t> datagram) {
    const Framing framing = frameDatagram(datagram);
    DatagramReplies result;
    for (const Packet& packet : framing.packets) {
        auto reply = readReply(packet);
        if (reply)
            result.replies.push_back(std::move(*reply));
        else
            result.errors.push_back(reply.error());
    }
    result.errors.insert(result.errors.end(), framing.errors.begin(), framing.errors.end());
    return result;
}

} // namespace stellwerk::z21
