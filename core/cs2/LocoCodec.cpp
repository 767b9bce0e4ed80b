// Management commands (document chapter 3): discovery, mfx bind/verify, speed, direction,
// functions and CV programming.

#include "cs2/CodecDetail.h"
#include "cs2/Fields.h"

#include <array>

namespace stellwerk::cs2 {
namespace {

using detail::BodyResult;
using detail::Reader;

constexpr std::array<NamedValue, 4> Directions{{{0, "keep"}, {1, "forward"}, {2, "backward"}, {3, "toggle"}}};
constexpr std::array<NamedValue, 2> Tracks{{{0, "programming"}, {1, "main"}}};
constexpr std::array<NamedValue, 4> DccModes{{{0, "direct"}, {1, "register"}, {2, "bit"}, {3, "reserved"}}};

// Discovery range values of the table in 3.1; everything else is reserved.
bool isDocumentedRange(std::uint8_t range) {
    return range <= 39 || (range >= 64 && range <= 96) || (range >= 98 && range <= 102);
}

std::string_view discoveryMode(std::optional<std::uint32_t> uid, std::optional<std::uint8_t> range) {
    if (!range)
        return "all-protocols";
    const unsigned r = *range;
    if (!uid && r <= 32)
        return "mfx-discovery-cycle"; // DLC 1: the station runs the whole search by itself
    if (r <= 32)
        return r == 0 ? "mfx-forced-registration" : "mfx-programming-track";
    if (r >= 64 && r <= 96)
        return "mfx-main-track";
    switch (r) {
    case 33:
        return "mm2-20khz";
    case 34:
        return "mm2-40khz";
    case 35:
        return "dcc-short-address";
    case 36:
        return "dcc-long-address";
    case 37:
        return "dcc-search";
    case 38:
        return "sx1-read-address";
    case 39:
        return "sx1-search";
    default:
        return "invalid-on-main-track";
    }
}

BodyResult decodeDiscovery(const Reader& r) {
    LocoDiscovery m;
    switch (r.size()) {
    case 0:
        return MessageBody(m);
    case 1:
        m.range = r.u8(0);
        break;
    case 5:
        m.uid = r.u32(0), m.range = r.u8(4);
        break;
    case 6:
        m.uid = r.u32(0), m.range = r.u8(4), m.ask = r.u8(5);
        break;
    default:
        return r.length("loco.discovery has 0, 1, 5 or 6 data bytes");
    }
    if (!isDocumentedRange(*m.range))
        return r.reserved("discovery range/protocol 40..63, 97 and above 102 are reserved");
    return MessageBody(m);
}

BodyResult decodeMfx(std::uint8_t command, const Reader& r) {
    if (r.size() < 6)
        return r.tooShort("mfx bind/verify needs an mfx UID and a SID (6 data bytes)");
    if (Command(command) == Command::MfxBind) {
        if (r.size() != 6)
            return r.length("mfx.bind has 6 data bytes");
        return MessageBody(MfxBind{r.u32(0), r.u16(4)});
    }
    if (r.size() > 7)
        return r.length("mfx.verify has 6 or 7 data bytes");
    MfxVerify m{r.u32(0), r.u16(4), std::nullopt};
    if (r.size() == 7)
        m.ask = r.u8(6);
    return MessageBody(m);
}

BodyResult decodeSpeed(const Reader& r) {
    if (r.size() == 4)
        return MessageBody(LocoSpeed{LocId(r.u32(0)), std::nullopt});
    if (r.size() != 6)
        return r.size() < 4 ? r.tooShort("loco.speed needs a Loc-ID (4 data bytes)")
                            : r.length("loco.speed has 4 (query) or 6 data bytes");
    if (r.u16(4) > 1023)
        return r.reserved("loco speed is a 10-bit value (0..1000, at most 1023)");
    return MessageBody(LocoSpeed{LocId(r.u32(0)), r.u16(4)});
}

BodyResult decodeDirection(const Reader& r) {
    if (r.size() == 4)
        return MessageBody(LocoDirection{LocId(r.u32(0)), std::nullopt});
    if (r.size() == 5)
        return MessageBody(LocoDirection{LocId(r.u32(0)), r.u8(4)});
    return r.size() < 4 ? r.tooShort("loco.direction needs a Loc-ID (4 data bytes)")
                        : r.length("loco.direction has 4 (query) or 5 data bytes");
}

BodyResult decodeFunction(const Reader& r) {
    if (r.size() < 5)
        return r.tooShort("loco.function needs a Loc-ID and a function number (5 data bytes)");
    if (r.size() == 7)
        return r.length("loco.function has 5, 6 or 8 data bytes");
    LocoFunction m{LocId(r.u32(0)), r.u8(4), std::nullopt, std::nullopt};
    if (m.function > 31)
        return r.reserved("loco functions are F0..F31");
    if (r.size() >= 6)
        m.value = r.u8(5);
    if (r.size() == 8)
        m.functionValue = r.u16(6);
    return MessageBody(m);
}

BodyResult decodeConfigRead(const Reader& r) {
    if (r.size() < 6)
        return r.tooShort("config.read needs a Loc-ID and a CV (6 data bytes)");
    ConfigRead m{LocId(r.u32(0)), CvAddress::unpack(r.u16(4)), std::nullopt, std::nullopt};
    if (r.size() == 7) {
        (r.response() ? m.value : m.count) = r.u8(6);
        return MessageBody(m);
    }
    if (r.size() == 6 && r.response())
        return MessageBody(m); // nothing could be read
    return r.length("config.read has 7 data bytes (6 in a failed answer)");
}

BodyResult decodeConfigWrite(const Reader& r) {
    if (r.size() < 8)
        return r.tooShort("config.write has 8 data bytes");
    ConfigWrite m{LocId(r.u32(0)), CvAddress::unpack(r.u16(4)), r.u8(6), r.u8(7)};
    if (!r.response() && m.mode() == DccProgrammingMode::Reserved)
        return r.reserved("DCC programming mode 0b11 is reserved");
    return MessageBody(m);
}

} // namespace

namespace detail {

BodyResult decodeManagement(std::uint8_t command, const Reader& r) {
    switch (Command(command)) {
    case Command::LocoDiscovery:
        return decodeDiscovery(r);
    case Command::MfxBind:
    case Command::MfxVerify:
        return decodeMfx(command, r);
    case Command::LocoSpeed:
        return decodeSpeed(r);
    case Command::LocoDirection:
        return decodeDirection(r);
    case Command::LocoFunction:
        return decodeFunction(r);
    case Command::ConfigRead:
        return decodeConfigRead(r);
    default:
        return decodeConfigWrite(r);
    }
}

void encode(const LocoDiscovery& m, Writer& w) {
    if (m.uid)
        w.u32(*m.uid);
    if (m.range || m.uid)
        w.u8(m.range.value_or(0));
    if (m.ask)
        w.u8(*m.ask);
}
void encode(const MfxBind& m, Writer& w) {
    w.u32(m.mfxUid).u16(m.sid);
}
void encode(const MfxVerify& m, Writer& w) {
    w.u32(m.mfxUid).u16(m.sid);
    if (m.ask)
        w.u8(*m.ask);
}
void encode(const LocoSpeed& m, Writer& w) {
    w.u32(m.loco.value());
    if (m.speed)
        w.u16(*m.speed);
}
void encode(const LocoDirection& m, Writer& w) {
    w.u32(m.loco.value());
    if (m.direction)
        w.u8(*m.direction);
}
void encode(const LocoFunction& m, Writer& w) {
    w.u32(m.loco.value()).u8(m.function);
    if (m.value || m.functionValue)
        w.u8(m.value.value_or(0));
    if (m.functionValue)
        w.u16(*m.functionValue);
}
void encode(const ConfigRead& m, Writer& w) {
    w.u32(m.loco.value()).u16(m.cv.packed());
    if (m.count)
        w.u8(*m.count);
    else if (m.value)
        w.u8(*m.value);
}
void encode(const ConfigWrite& m, Writer& w) {
    w.u32(m.loco.value()).u16(m.cv.packed()).u8(m.value).u8(m.flags);
}

} // namespace detail

void LocoDiscovery::bind(FieldBinder& b) {
    b.number("uid", uid, FieldFormat::Hex);
    b.number("range", range);
    b.number("ask", ask, FieldFormat::Hex);
    b.note("mode", discoveryMode(uid, range));
}

void MfxBind::bind(FieldBinder& b) {
    b.number("uid", mfxUid, FieldFormat::Hex);
    b.number("sid", sid);
}

void MfxVerify::bind(FieldBinder& b) {
    b.number("uid", mfxUid, FieldFormat::Hex);
    b.number("sid", sid);
    b.number("ask", ask, FieldFormat::Hex);
}

void LocoSpeed::bind(FieldBinder& b) {
    b.loco("locId", loco);
    b.number("speed", speed);
}

void LocoDirection::bind(FieldBinder& b) {
    b.loco("locId", loco);
    if (direction && *direction > 3) {
        b.note("direction", "keep"); // the document: any other value keeps the direction
        b.number("value", direction);
        return;
    }
    b.named("direction", direction, Directions);
    if (!direction)
        b.number("value", direction); // building with a raw value
}

void LocoFunction::bind(FieldBinder& b) {
    b.loco("locId", loco);
    b.number("function", function, FieldFormat::Decimal, 1, 31);
    b.number("value", value);
    b.number("functionValue", functionValue);
}

static void bindCv(FieldBinder& b, CvAddress& cv) {
    b.number("cvNumber", cv.number, FieldFormat::Decimal, 1, 0x3FF);
    b.number("cvIndex", cv.index, FieldFormat::Decimal, 1, 0x3F);
}

void ConfigRead::bind(FieldBinder& b) {
    b.loco("locId", loco);
    bindCv(b, cv);
    if (b.response())
        b.number("value", value);
    else
        b.number("count", count);
}

void ConfigWrite::bind(FieldBinder& b) {
    b.loco("locId", loco);
    bindCv(b, cv);
    b.number("value", value);
    b.number("flags", flags, FieldFormat::Hex);
    if (b.response()) {
        b.flag("writeOk", flags, WriteOk);
        b.flag("verifyOk", flags, VerifyOk);
        return;
    }
    b.named("track", flags, Tracks, MainTrack);
    b.flag("multiByte", flags, MultiByte);
    b.named("mode", flags, DccModes, 0x30);
}

} // namespace stellwerk::cs2
