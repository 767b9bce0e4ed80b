#include "z21/RequestCodec.h"

#include <optional>
#include <string>

namespace stellwerk::z21 {

namespace {

constexpr std::size_t MaxUnknownData = 64;
constexpr std::uint8_t HighestFunction = 31;

using Bytes = std::span<const std::uint8_t>;
using Read = std::optional<RequestBody>;

std::string hexText(unsigned value) {
    static constexpr char Digits[] = "0123456789ABCDEF";
    std::string text;
    do {
        text.insert(text.begin(), Digits[value & 0xF]);
        value >>= 4;
    } while (value != 0);
    return "0x" + (text.size() % 2 ? "0" + text : text);
}

PacketError wrongLength(const Packet& packet, std::size_t expected) {
    return {packet.offset, PacketProblem::WrongLength, packet.header,
            "header " + hexText(packet.header) + " needs " + std::to_string(expected + 4) +
                " bytes, DataLen is " + std::to_string(packet.data.size() + 4)};
}

UnknownRequest unknown(const Packet& packet) {
    const Bytes kept = packet.data.first(std::min(packet.data.size(), MaxUnknownData));
    return {packet.header, {kept.begin(), kept.end()}};
}

std::optional<DecoderFormat> formatOf(std::uint8_t mode) {
    if (mode > 1)
        return std::nullopt;
    return DecoderFormat(mode);
}

// ---- LAN commands without X-bus tunnel (chapters 2 and 3) ----------------------------------------------

// The data length a LAN header needs; nullopt for headers this codec does not read.
std::optional<std::size_t> lanDataSize(std::uint16_t header) {
    switch (header) {
    case 0x10:
    case 0x18:
    case 0x1A:
    case 0x30:
    case 0x51:
    case 0x85:
        return 0;
    case 0x50:
        return 4;
    case 0x60:
    case 0x70:
        return 2;
    case 0x61:
    case 0x71:
        return 3;
    default:
        return std::nullopt;
    }
}

Read readModeRequest(std::uint16_t header, Bytes data) {
    const std::uint16_t address = readBigEndian16(data);
    if (header == 0x60)
        return GetLocoMode{address};
    if (header == 0x70)
        return GetTurnoutMode{address};
    const auto format = formatOf(data[2]);
    if (!format)
        return std::nullopt;
    if (header == 0x61)
        return SetLocoMode{address, *format};
    return SetTurnoutMode{address, *format};
}

Read readLan(std::uint16_t header, Bytes data) {
    switch (header) {
    case 0x10:
        return GetSerialNumber{};
    case 0x18:
        return GetCode{};
    case 0x1A:
        return GetHardwareInfo{};
    case 0x30:
        return Logoff{};
    case 0x50:
        return SetBroadcastFlags{readLittleEndian32(data)};
    case 0x51:
        return GetBroadcastFlags{};
    case 0x85:
        return GetSystemState{};
    default:
        return readModeRequest(header, data);
    }
}

// ---- X-bus commands (x = X-header and data bytes, without the XOR byte) -------------------------------

Read readX21(Bytes x) {
    switch (x[1]) {
    case 0x21:
        return GetXVersion{};
    case 0x24:
        return GetXStatus{};
    case 0x80:
        return SetTrackPowerOff{};
    case 0x81:
        return SetTrackPowerOn{};
    default:
        return std::nullopt;
    }
}

Read readLocoCommand(Bytes x) {
    const std::uint16_t address = locoAddress(x[2], x[3]);
    if (x[1] == 0xF8) {
        const auto action = std::uint8_t(x[4] >> 6);
        const auto function = std::uint8_t(x[4] & 0x3F);
        if (action == 3 || function > HighestFunction)
            return std::nullopt;
        return SetLocoFunction{address, function, FunctionAction(action)};
    }
    const auto mode = (x[1] & 0xF0) == 0x10 ? modeFromDriveCode(x[1] & 0x0F) : std::nullopt;
    if (!mode)
        return std::nullopt;
    return SetLocoDrive{address, speedFromByte(*mode, x[4])};
}

Read readTurnout(Bytes x) {
    const std::uint16_t address = readBigEndian16(x.subspan(1));
    if (x[0] == 0x43)
        return GetTurnoutInfo{address};
    return SetTurnout{address, (x[3] & 0x01) != 0, (x[3] & 0x08) != 0, (x[3] & 0x20) != 0};
}

// The X-bus commands read: X-header, DB0 (or -1 for any), the length of x, and the reader.
struct XCommand {
    std::uint8_t xHeader;
    int db0;
    std::size_t size;
    Read (*read)(Bytes);
};

constexpr XCommand XCommands[] = {
    {0x21, -1, 2, readX21},
    {0x80, -1, 1, [](Bytes) -> Read { return SetStop{}; }},
    {0xF1, 0x0A, 2, [](Bytes) -> Read { return GetFirmwareVersion{}; }},
    {0xE3, 0xF0, 4, [](Bytes x) -> Read { return GetLocoInfo{locoAddress(x[2], x[3])}; }},
    {0xE4, -1, 5, readLocoCommand},
    {0x92, -1, 3, [](Bytes x) -> Read { return SetLocoEmergencyStop{locoAddress(x[1], x[2])}; }},
    {0x43, -1, 3, readTurnout},
    {0x53, -1, 4, readTurnout},
};

const XCommand* xCommandOf(Bytes x) {
    for (const XCommand& command : XCommands) {
        const bool db0Matches = command.db0 < 0 || (x.size() > 1 && x[1] == command.db0);
        if (x[0] == command.xHeader && db0Matches)
            return &command;
    }
    return nullptr;
}

Expected<Request, PacketError> readXBus(const Packet& packet) {
    if (packet.data.size() < 2)
        return wrongLength(packet, 2);
    const Bytes x = packet.data.first(packet.data.size() - 1);
    const bool wrongChecksum = xorOf(x) != packet.data.back();
    const XCommand* command = xCommandOf(x);
    if (command && x.size() != command->size)
        return wrongLength(packet, command->size + 1);
    const Read read = command ? command->read(x) : std::nullopt;
    return Request{read ? *read : RequestBody(unknown(packet)), wrongChecksum};
}

} // namespace

Expected<Request, PacketError> readRequest(const Packet& packet) {
    if (packet.header == XBusHeader)
        return readXBus(packet);
    const auto size = lanDataSize(packet.header);
    if (!size)
        return Request{unknown(packet)};
    if (packet.data.size() != *size)
        return wrongLength(packet, *size);
    const Read read = readLan(packet.header, packet.data);
    return Request{read ? *read : RequestBody(unknown(packet))};
}

DatagramRequests readRequests(std::span<const std::uint8_t> datagram) {
    const Framing framing = frameDatagram(datagram);
    DatagramRequests result;
    for (const Packet& packet : framing.packets) {
        auto request = readRequest(packet);
        if (request)
            result.requests.push_back(std::move(*request));
        else
            result.errors.push_back(request.error());
    }
    result.errors.insert(result.errors.end(), framing.errors.begin(), framing.errors.end());
    return result;
}

} // namespace stellwerk::z21
