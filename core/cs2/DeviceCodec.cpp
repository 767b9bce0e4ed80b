// Device commands (document chapter 6 and the 0x19..0x1D range): ping, update, bootloaders and
// the status data configuration stream.

#include "cs2/CodecDetail.h"
#include "cs2/Fields.h"
#include "cs2/Hash.h"

#include <array>

namespace stellwerk::cs2 {
namespace {

using detail::be16;
using detail::be32;
using detail::BodyResult;
using detail::Reader;

constexpr std::array<NamedValue, 3> StatusForms{{{0, "request"}, {1, "packet"}, {2, "end"}}};

BodyResult decodePing(const Reader& r) {
    if (r.size() == 0)
        return MessageBody(Ping{});
    if (r.size() == 8)
        return MessageBody(Ping{DeviceIdentity{r.u32(0), r.u8(4), r.u8(5), r.u16(6)}});
    return r.length("ping has 0 (query) or 8 (answer) data bytes");
}

template <class T>
BodyResult rawWithLengths(const Reader& r, std::initializer_list<std::size_t> lengths,
                          std::string_view error) {
    for (auto length : lengths)
        if (r.size() == length)
            return MessageBody(T{r.raw()});
    return r.length(error);
}

BodyResult decodeStatusData(const Reader& r) {
    StatusDataConfig m;
    if (!r.response()) {
        if (r.size() != 5)
            return r.size() < 5
                       ? r.tooShort("statusdata.config request needs a UID and an index (5 data bytes)")
                       : r.length("statusdata.config request has 5 data bytes");
        m.device = r.u32(0), m.index = r.u8(4);
        return MessageBody(m);
    }
    if (r.size() == 5 || r.size() == 6) {
        m.form = StatusDataConfig::Form::End;
        m.device = r.u32(0), m.index = r.u8(4);
        if (r.size() == 6)
            m.packetCount = r.u8(5);
        return MessageBody(m);
    }
    if (r.size() == 0)
        return r.tooShort("statusdata.config answer packets carry data");
    m.form = StatusDataConfig::Form::Packet;
    m.packet = r.raw();
    return MessageBody(m);
}

std::string_view bootloaderCode(std::uint8_t code) {
    switch (code) {
    case 0x11:
        return "start-application";
    case 0x44:
        return "select-block";
    case 0x88:
        return "block-crc-ok";
    case 0xF5:
        return "update-end";
    default:
        return code >= 0xF0 && code <= 0xF4 ? "error" : "unknown";
    }
}

} // namespace

std::string_view deviceTypeName(std::uint16_t deviceType) {
    switch (deviceType) {
    case 0x0000:
        return "Track format processor 60213/60214 or booster 60173/60174";
    case 0x0010:
        return "Gleisbox 60112/60113";
    case 0x0011:
        return "Gleisbox 60116";
    case 0x0020:
        return "Connect 6021 (60128)";
    case 0x0030:
    case 0x0031:
    case 0x0032:
    case 0x0033:
    case 0x0034:
        return "Mobile Station 2";
    case 0x0040:
        return "Link S88";
    case 0xEEEE:
        return "CS2 software (PC)";
    case 0xFFE0:
        return "Wireless device";
    case 0xFFF0:
        return "CS2 slave GUI";
    case 0xFFFF:
        return "Central Station GUI (master)";
    default:
        return "unknown device type";
    }
}

namespace detail {

BodyResult decodeDevice(std::uint8_t command, const Reader& r) {
    switch (Command(command)) {
    case Command::Ping:
        return decodePing(r);
    case Command::UpdateOffer:
        return rawWithLengths<UpdateOffer>(r, {8}, "update.offer has 8 data bytes");
    case Command::ReadConfigData:
        return rawWithLengths<ReadConfigData>(r, {4, 8}, "update.read-config-data has 4 or 8 data bytes");
    case Command::BootloaderCan:
        return rawWithLengths<BootloaderCan>(r, {0, 5, 6, 7, 8},
                                             "bootloader.can has 0, 5, 6, 7 or 8 data bytes");
    case Command::BootloaderTrack:
        return rawWithLengths<BootloaderTrack>(r, {4, 5, 6, 7, 8}, "bootloader.track has 4 to 8 data bytes");
    default:
        return decodeStatusData(r);
    }
}

void encode(const Ping& m, Writer& w) {
    if (m.identity)
        w.u32(m.identity->uid)
            .u8(m.identity->versionMajor)
            .u8(m.identity->versionMinor)
            .u16(m.identity->deviceType);
}
void encode(const UpdateOffer& m, Writer& w) {
    w.raw(m.raw);
}
void encode(const ReadConfigData& m, Writer& w) {
    w.raw(m.raw);
}
void encode(const BootloaderCan& m, Writer& w) {
    w.raw(m.raw);
}
void encode(const BootloaderTrack& m, Writer& w) {
    w.raw(m.raw);
}
void encode(const StatusDataConfig& m, Writer& w) {
    if (m.form == StatusDataConfig::Form::Packet) {
        w.raw(m.packet);
        return;
    }
    w.u32(m.device).u8(m.index);
    if (m.form == StatusDataConfig::Form::End && m.packetCount)
        w.u8(*m.packetCount);
}

} // namespace detail

void Ping::bind(FieldBinder& b) {
    std::optional<std::uint32_t> uid;
    std::optional<std::uint16_t> version, type;
    if (identity) {
        uid = identity->uid;
        version = std::uint16_t((identity->versionMajor << 8) | identity->versionMinor);
        type = identity->deviceType;
    }
    b.number("uid", uid, FieldFormat::Hex);
    b.version("version", version);
    b.number("deviceType", type, FieldFormat::Hex);
    if (type)
        b.note("deviceName", deviceTypeName(*type));
    if (uid || version || type) {
        const std::uint16_t v = version.value_or(0);
        identity = DeviceIdentity{uid.value_or(0), std::uint8_t(v >> 8), std::uint8_t(v), type.value_or(0)};
    }
}

void UpdateOffer::bind(FieldBinder& b) {
    b.bytes("bytes", raw);
}
void ReadConfigData::bind(FieldBinder& b) {
    b.bytes("bytes", raw);
    if (raw.size >= 4)
        b.fixed("uid", be32(raw, 0), FieldFormat::Hex);
}

void BootloaderCan::bind(FieldBinder& b) {
    b.bytes("bytes", raw);
    if (raw.size == 0) {
        b.note("mode", "query");
    } else if (raw.size == 8 && b.response()) {
        DeviceIdentity id{be32(raw, 0), raw.bytes[4], raw.bytes[5], be16(raw, 6)};
        b.fixed("uid", id.uid, FieldFormat::Hex);
        b.note("version", std::to_string(id.versionMajor) + "." + std::to_string(id.versionMinor));
        b.fixed("deviceType", id.deviceType, FieldFormat::Hex);
        b.note("deviceName", deviceTypeName(id.deviceType));
    } else if (raw.size == 8) {
        b.fixed("packet", packetNumberFromHash(b.hash()), FieldFormat::Decimal);
    } else {
        b.fixed("uid", be32(raw, 0), FieldFormat::Hex);
        b.fixed("subcommand", raw.bytes[4], FieldFormat::Hex);
        b.note("mode", bootloaderCode(raw.bytes[4]));
        if (raw.size == 6)
            b.fixed("value", raw.bytes[5], FieldFormat::Decimal);
        if (raw.size == 7)
            b.fixed("crc", be16(raw, 5), FieldFormat::Hex);
    }
}

void BootloaderTrack::bind(FieldBinder& b) {
    b.bytes("bytes", raw);
    if (raw.size >= 4)
        b.fixed("uid", be32(raw, 0), FieldFormat::Hex);
}

void StatusDataConfig::bind(FieldBinder& b) {
    b.enumerated("form", form, StatusForms);
    if (form == Form::Packet) {
        b.fixed("packet", packetNumberFromHash(b.hash()), FieldFormat::Decimal);
        b.bytes("bytes", packet);
        return;
    }
    b.number("uid", device, FieldFormat::Hex);
    b.number("index", index);
    if (form == Form::End)
        b.number("count", packetCount);
}

} // namespace stellwerk::cs2
