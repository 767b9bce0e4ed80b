#include "cs2/LocId.h"

#include <array>

namespace stellwerk::cs2 {
namespace {

struct RangeSpan {
    std::uint32_t first;
    std::uint32_t last;
    LocIdRange range;
};

constexpr std::array<RangeSpan, 19> Ranges{{
    {0x0000, 0x03FF, LocIdRange::Mm2},
    {0x0400, 0x07FF, LocIdRange::Reserved},
    {0x0800, 0x0BFF, LocIdRange::Sx1},
    {0x0C00, 0x0FFF, LocIdRange::Reserved},
    {0x1000, 0x13FF, LocIdRange::Mm2FunctionDecoder},
    {0x1400, 0x17FF, LocIdRange::Reserved},
    {0x1800, 0x1BFF, LocIdRange::Private},
    {0x1C00, 0x1FFF, LocIdRange::Company},
    {0x2000, 0x23FF, LocIdRange::Mm2Loco20kHz},
    {0x2400, 0x27FF, LocIdRange::Reserved},
    {0x2800, 0x2BFF, LocIdRange::Sx1Accessory},
    {0x2C00, 0x2FFF, LocIdRange::Traction},
    {0x3000, 0x33FF, LocIdRange::Mm2Accessory},
    {0x3400, 0x37FF, LocIdRange::Reserved},
    {0x3800, 0x3FFF, LocIdRange::DccAccessory},
    {0x4000, 0x7FFF, LocIdRange::Mfx},
    {0x8000, 0xBFFF, LocIdRange::Sx2},
    {0xC000, 0xFFFF, LocIdRange::Dcc},
    {0x10000, 0xFFFFFFFF, LocIdRange::DeviceUid},
}};

const RangeSpan& spanOf(std::uint32_t value) {
    for (const auto& span : Ranges)
        if (value >= span.first && value <= span.last)
            return span;
    return Ranges.back();
}

struct ProtocolSpan {
    Protocol protocol;
    std::uint32_t base;
    std::uint32_t size;
    bool accessory;
    std::string_view name;
};

constexpr std::array<ProtocolSpan, 8> Protocols{{
    {Protocol::Mm2, 0x0000, 0x0400, false, "mm2"},
    {Protocol::Sx1, 0x0800, 0x0400, false, "sx1"},
    {Protocol::Mfx, 0x4000, 0x4000, false, "mfx"},
    {Protocol::Sx2, 0x8000, 0x4000, false, "sx2"},
    {Protocol::Dcc, 0xC000, 0x4000, false, "dcc"},
    {Protocol::Mm2Accessory, 0x3000, 0x0400, true, "mm2-accessory"},
    {Protocol::DccAccessory, 0x3800, 0x0800, true, "dcc-accessory"},
    {Protocol::Sx1Accessory, 0x2800, 0x0400, true, "sx1-accessory"},
}};

const ProtocolSpan* protocolSpan(Protocol protocol) {
    for (const auto& span : Protocols)
        if (span.protocol == protocol)
            return &span;
    return nullptr;
}

} // namespace

std::string_view protocolName(Protocol protocol) {
    const auto* span = protocolSpan(protocol);
    return span ? span->name : "other";
}

std::optional<Protocol> protocolFromName(std::string_view name) {
    for (const auto& span : Protocols)
        if (span.name == name)
            return span.protocol;
    if (name == "other")
        return Protocol::Other;
    return std::nullopt;
}

std::string_view rangeName(LocIdRange range) {
    switch (range) {
    case LocIdRange::Mm2:
        return "MM2";
    case LocIdRange::Reserved:
        return "reserved";
    case LocIdRange::Sx1:
        return "SX1";
    case LocIdRange::Mm2FunctionDecoder:
        return "MM2 function decoder (reserved)";
    case LocIdRange::Private:
        return "private use";
    case LocIdRange::Company:
        return "company use";
    case LocIdRange::Mm2Loco20kHz:
        return "MM2 20 kHz loco (reserved)";
    case LocIdRange::Sx1Accessory:
        return "SX1 accessory";
    case LocIdRange::Traction:
        return "traction (GUI-internal)";
    case LocIdRange::Mm2Accessory:
        return "MM2 accessory";
    case LocIdRange::DccAccessory:
        return "DCC accessory";
    case LocIdRange::Mfx:
        return "mfx";
    case LocIdRange::Sx2:
        return "SX2";
    case LocIdRange::Dcc:
        return "DCC";
    case LocIdRange::DeviceUid:
        return "device UID";
    }
    return "reserved";
}

std::optional<LocId> LocId::fromAddress(Protocol protocol, std::uint32_t address) {
    const auto* span = protocolSpan(protocol);
    if (!span)
        return std::nullopt;
    if (span->accessory) {
        if (address < 1 || address > span->size)
            return std::nullopt;
        return LocId(span->base + address - 1);
    }
    if (address >= span->size)
        return std::nullopt;
    return LocId(span->base + address);
}

LocIdRange LocId::range() const {
    return spanOf(value_).range;
}

Protocol LocId::protocol() const {
    switch (range()) {
    case LocIdRange::Mm2:
        return Protocol::Mm2;
    case LocIdRange::Sx1:
        return Protocol::Sx1;
    case LocIdRange::Mfx:
        return Protocol::Mfx;
    case LocIdRange::Sx2:
        return Protocol::Sx2;
    case LocIdRange::Dcc:
        return Protocol::Dcc;
    case LocIdRange::Mm2Accessory:
        return Protocol::Mm2Accessory;
    case LocIdRange::DccAccessory:
        return Protocol::DccAccessory;
    case LocIdRange::Sx1Accessory:
        return Protocol::Sx1Accessory;
    default:
        return Protocol::Other;
    }
}

std::uint32_t LocId::offset() const {
    return value_ - spanOf(value_).first;
}

bool LocId::isAccessory() const {
    const auto* span = protocolSpan(protocol());
    return span && span->accessory;
}

std::uint32_t LocId::address() const {
    return isAccessory() ? offset() + 1 : offset();
}

} // namespace stellwerk::cs2
