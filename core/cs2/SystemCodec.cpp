// System commands (0x00, document chapter 2): decode, encode and fields of each sub-command.

#include "cs2/CodecDetail.h"
#include "cs2/Fields.h"

#include <array>

namespace stellwerk::cs2 {
namespace {

enum Sub : std::uint8_t {
    Stop = 0x00,
    Go = 0x01,
    Halt = 0x02,
    EmergencyStop = 0x03,
    CycleEnd = 0x04,
    ProtocolSub = 0x05,
    SwitchTime = 0x06,
    FastRead = 0x07,
    TrackProtocol = 0x08,
    RegistrationCounter = 0x09,
    OverloadSub = 0x0A,
    Status = 0x0B,
    DeviceIdSub = 0x0C,
    Seek = 0x30,
    Reset = 0x80,
};

constexpr std::array<NamedValue, 3> Mm2Protocols{
    {{0, "mm2-2040"}, {1, "mm2-loco-20khz"}, {2, "mm2-function-40khz"}}};
constexpr std::array<NamedValue, 5> DccProtocols{{{0, "dcc-short-28"},
                                                  {1, "dcc-short-14"},
                                                  {2, "dcc-short-126"},
                                                  {3, "dcc-long-28"},
                                                  {4, "dcc-long-126"}}};
constexpr std::array<NamedValue, 5> SeekCodes{
    {{0x00, "stop"}, {0x01, "wait-bit"}, {0x02, "wait-bytes"}, {0x82, "byte-answer"}, {0x83, "bit-answer"}}};

std::string_view protocolList(std::uint8_t mask) {
    static constexpr std::array<std::string_view, 8> Lists{"none", "mm2",     "mfx",     "mm2,mfx",
                                                           "dcc",  "mm2,dcc", "mfx,dcc", "mm2,mfx,dcc"};
    return Lists[mask & 0x07];
}

void bindTarget(FieldBinder& b, std::uint32_t& uid, std::uint8_t sub) {
    b.number("uid", uid, FieldFormat::Hex);
    b.fixed("subcommand", sub, FieldFormat::Hex);
}

void bindTarget(FieldBinder& b, LocId& loco, std::uint8_t sub) {
    b.loco("locId", loco);
    b.fixed("subcommand", sub, FieldFormat::Hex);
}

using detail::BodyResult;
using detail::Reader;

template <class T>
BodyResult targetOnly(const Reader& r, std::string_view lengthError) {
    if (r.size() != 5)
        return r.length(lengthError);
    T m;
    if constexpr (requires { m.target; })
        m.target = r.u32(0);
    else
        m.loco = LocId(r.u32(0));
    return MessageBody(m);
}

BodyResult decodeProtocol(const Reader& r) {
    if (r.size() != 6)
        return r.length("system.loco-protocol has 6 data bytes");
    LocoProtocol m{LocId(r.u32(0)), r.u8(5)};
    if (m.loco.protocol() == Protocol::Mm2 && m.trackProtocol > 2)
        return r.reserved("MM2 sub-protocols are 0..2");
    if (m.loco.protocol() == Protocol::Dcc && m.trackProtocol > 4)
        return r.reserved("DCC sub-protocols are 0..4");
    return MessageBody(m);
}

BodyResult decodeSwitchTime(const Reader& r) {
    if (r.size() == 5)
        return MessageBody(AccessorySwitchTime{r.u32(0), std::nullopt});
    if (r.size() == 7)
        return MessageBody(AccessorySwitchTime{r.u32(0), r.u16(5)});
    return r.length("system.accessory-switch-time has 7 data bytes (5 without a time)");
}

BodyResult decodeTrackProtocols(const Reader& r) {
    if (r.size() != 6)
        return r.length("system.track-protocols has 6 data bytes");
    if (r.u8(5) & 0xF8)
        return r.reserved("track protocol bits 3..7 are reserved");
    return MessageBody(TrackProtocols{r.u32(0), r.u8(5)});
}

BodyResult decodeStatus(const Reader& r) {
    SystemStatus m{r.u32(0), 0, std::nullopt, std::nullopt};
    if (r.size() < 6)
        return r.tooShort("system.status needs a channel (6 data bytes)");
    m.channel = r.u8(5);
    if (r.size() == 7) {
        if (r.u8(6) > 1)
            return r.reserved("system.status acknowledgement must be 0 (rejected) or 1 (accepted)");
        m.accepted = r.u8(6) == 1;
    } else if (r.size() == 8) {
        m.value = r.u16(6);
    }
    return MessageBody(m);
}

BodyResult decodeSeek(const Reader& r) {
    if (r.size() < 6)
        return r.tooShort("system.mfx-seek needs a code (6 data bytes)");
    MfxSeek m{r.u32(0), r.u8(5), std::nullopt, std::nullopt};
    if (r.size() >= 7)
        m.argument = r.u8(6);
    if (r.size() == 8)
        m.answer = r.u8(7);
    return MessageBody(m);
}

template <std::size_t Size, class Fill>
BodyResult exact(const Reader& r, std::string_view lengthError, Fill fill) {
    if (r.size() < Size)
        return r.tooShort(lengthError);
    if (r.size() != Size)
        return r.length(lengthError);
    return MessageBody(fill());
}

} // namespace

namespace detail {

BodyResult decodeSystem(const Reader& r) {
    if (r.size() < 5)
        return r.tooShort("system commands need a UID and a sub-command (5 data bytes)");
    switch (r.u8(4)) {
    case Stop:
        return targetOnly<SystemStop>(r, "system.stop has 5 data bytes");
    case Go:
        return targetOnly<SystemGo>(r, "system.go has 5 data bytes");
    case Halt:
        return targetOnly<SystemHalt>(r, "system.halt has 5 data bytes");
    case EmergencyStop:
        return targetOnly<LocoEmergencyStop>(r, "system.loco-emergency-stop has 5 data bytes");
    case CycleEnd:
        return targetOnly<LocoCycleEnd>(r, "system.loco-cycle-end has 5 data bytes");
    case ProtocolSub:
        return decodeProtocol(r);
    case SwitchTime:
        return decodeSwitchTime(r);
    case FastRead:
        return exact<7>(r, "system.mfx-fast-read has 7 data bytes", [&] {
            return MfxFastRead{r.u32(0), r.u16(5)};
        });
    case TrackProtocol:
        return decodeTrackProtocols(r);
    case RegistrationCounter:
        return exact<7>(r, "system.mfx-registration-counter has 7 data bytes", [&] {
            return MfxRegistrationCounter{r.u32(0), r.u16(5)};
        });
    case OverloadSub:
        return exact<6>(r, "system.overload has 6 data bytes", [&] { return Overload{r.u32(0), r.u8(5)}; });
    case Status:
        return decodeStatus(r);
    case DeviceIdSub:
        if (r.size() == 5)
            return MessageBody(DeviceId{r.u32(0), std::nullopt});
        if (r.size() == 7)
            return MessageBody(DeviceId{r.u32(0), r.u16(5)});
        return r.length("system.device-id has 5 (query) or 7 data bytes");
    case Seek:
        return decodeSeek(r);
    case Reset:
        return exact<6>(r, "system.reset has 6 data bytes", [&] { return SystemReset{r.u32(0), r.u8(5)}; });
    default:
        return MessageBody(Unknown{0x00, r.raw()});
    }
}

void encode(const SystemStop& m, Writer& w) {
    w.u32(m.target).u8(Stop);
}
void encode(const SystemGo& m, Writer& w) {
    w.u32(m.target).u8(Go);
}
void encode(const SystemHalt& m, Writer& w) {
    w.u32(m.target).u8(Halt);
}
void encode(const LocoEmergencyStop& m, Writer& w) {
    w.u32(m.loco.value()).u8(EmergencyStop);
}
void encode(const LocoCycleEnd& m, Writer& w) {
    w.u32(m.loco.value()).u8(CycleEnd);
}
void encode(const LocoProtocol& m, Writer& w) {
    w.u32(m.loco.value()).u8(ProtocolSub).u8(m.trackProtocol);
}
void encode(const AccessorySwitchTime& m, Writer& w) {
    w.u32(m.target).u8(SwitchTime);
    if (m.time10ms)
        w.u16(*m.time10ms);
}
void encode(const MfxFastRead& m, Writer& w) {
    w.u32(m.sender).u8(FastRead).u16(m.sid);
}
void encode(const TrackProtocols& m, Writer& w) {
    w.u32(m.target).u8(TrackProtocol).u8(m.mask);
}
void encode(const MfxRegistrationCounter& m, Writer& w) {
    w.u32(m.target).u8(RegistrationCounter).u16(m.counter);
}
void encode(const Overload& m, Writer& w) {
    w.u32(m.sender).u8(OverloadSub).u8(m.channel);
}
void encode(const SystemStatus& m, Writer& w) {
    w.u32(m.device).u8(Status).u8(m.channel);
    if (m.accepted)
        w.u8(*m.accepted ? 1 : 0);
    else if (m.value)
        w.u16(*m.value);
}
void encode(const DeviceId& m, Writer& w) {
    w.u32(m.target).u8(DeviceIdSub);
    if (m.deviceId)
        w.u16(*m.deviceId);
}
void encode(const SystemReset& m, Writer& w) {
    w.u32(m.target).u8(Reset).u8(m.resetTarget);
}
void encode(const MfxSeek& m, Writer& w) {
    w.u32(m.target).u8(Seek).u8(m.code);
    if (m.argument || m.answer)
        w.u8(m.argument.value_or(0));
    if (m.answer)
        w.u8(*m.answer);
}

} // namespace detail

void SystemStop::bind(FieldBinder& b) {
    bindTarget(b, target, Stop);
}
void SystemGo::bind(FieldBinder& b) {
    bindTarget(b, target, Go);
}
void SystemHalt::bind(FieldBinder& b) {
    bindTarget(b, target, Halt);
}
void LocoEmergencyStop::bind(FieldBinder& b) {
    bindTarget(b, loco, EmergencyStop);
}
void LocoCycleEnd::bind(FieldBinder& b) {
    bindTarget(b, loco, CycleEnd);
}

void LocoProtocol::bind(FieldBinder& b) {
    bindTarget(b, loco, ProtocolSub);
    if (loco.protocol() == Protocol::Mm2)
        b.named("value", trackProtocol, Mm2Protocols);
    else if (loco.protocol() == Protocol::Dcc)
        b.named("value", trackProtocol, DccProtocols);
    else
        b.number("value", trackProtocol);
}

void AccessorySwitchTime::bind(FieldBinder& b) {
    bindTarget(b, target, SwitchTime);
    b.number("switchTimeMs", time10ms, FieldFormat::Decimal, 10);
}

void MfxFastRead::bind(FieldBinder& b) {
    bindTarget(b, sender, FastRead);
    b.number("sid", sid);
}

void TrackProtocols::bind(FieldBinder& b) {
    bindTarget(b, target, TrackProtocol);
    b.number("value", mask, FieldFormat::Hex);
    b.note("protocols", protocolList(mask));
}

void MfxRegistrationCounter::bind(FieldBinder& b) {
    bindTarget(b, target, RegistrationCounter);
    b.number("value", counter);
}

void Overload::bind(FieldBinder& b) {
    bindTarget(b, sender, OverloadSub);
    b.number("channel", channel);
}

void SystemStatus::bind(FieldBinder& b) {
    bindTarget(b, device, Status);
    b.number("channel", channel);
    b.number("value", value);
    b.boolean("accepted", accepted);
}

void DeviceId::bind(FieldBinder& b) {
    bindTarget(b, target, DeviceIdSub);
    b.number("device", deviceId, FieldFormat::Hex);
}

void SystemReset::bind(FieldBinder& b) {
    bindTarget(b, target, Reset);
    b.number("value", resetTarget, FieldFormat::Hex);
}

void MfxSeek::bind(FieldBinder& b) {
    bindTarget(b, target, Seek);
    b.named("mode", code, SeekCodes);
    b.number("argument", argument);
    b.number("value", answer);
}

} // namespace stellwerk::cs2
