#include "orc/CodecDetail.h"

// Groups 0x80 System and 0x81 Lok Control (001 §Befehlssatz, l. 489-1196; notes A2 #1-#20).

namespace stellwerk::orc::detail {
namespace {

namespace sub {
inline constexpr std::uint8_t AllOff = 0x00;
inline constexpr std::uint8_t AllOn = 0x01;
inline constexpr std::uint8_t Overload = 0x0A;
inline constexpr std::uint8_t LocoStop = 0x00;
inline constexpr std::uint8_t Speed = 0x01;
inline constexpr std::uint8_t SpeedByUid = 0x02;
inline constexpr std::uint8_t Functions = 0x03;
inline constexpr std::uint8_t Function = 0x04;
} // namespace sub

Message systemSwitch(const can::CanFrame& frame, bool on) {
    const Data d{frame};
    const std::optional<Target> target = targetOf(d);
    if (d.answer())
        return unknown(frame, "Alles Aus / Alles EIN are commands (D=0)");
    if (!target)
        return unknown(frame, "Alles Aus / Alles EIN take DLC 1, 3 (Ziel-Id) or 5 (Ziel-UID)");
    return on ? Message(AllOn{originOf(frame), *target}) : Message(AllOff{originOf(frame), *target});
}

Message locoStop(const can::CanFrame& frame) {
    const Data d{frame};
    const std::optional<Target> target = targetOf(d);
    if (d.answer())
        return unknown(frame, "Lok Nothalt is a command (D=0)");
    if (!target)
        return unknown(frame, "Lok Nothalt takes DLC 1, 3 (Ziel-Id) or 5 (Ziel-UID)");
    return LocoStop{originOf(frame), *target};
}

Message speed(const can::CanFrame& frame) {
    const Data d{frame};
    if (d.size() == 3 && !d.answer())
        return LocoSpeedQuery{originOf(frame), d.u16(1)};
    if (d.size() == 5)
        return LocoSpeed{originOf(frame), d.answer(), d.u16(1), d.u16(3)};
    if (d.size() == 7)
        return LocoSpeedByUid{originOf(frame), d.answer(), d.u32(1), d.u16(5), true};
    return unknown(frame,
                   "Lok Speed 0x01 takes DLC 3 (query, D=0), 5 (Ziel-Id, speed) or 7 (Ziel-UID, speed)");
}

Message speedByUid(const can::CanFrame& frame) {
    const Data d{frame};
    if (d.size() == 5 && !d.answer())
        return LocoSpeedQueryByUid{originOf(frame), d.u32(1)};
    if (d.size() == 7)
        return LocoSpeedByUid{originOf(frame), d.answer(), d.u32(1), d.u16(5), false};
    return unknown(frame, "Lok Speed 0x02 takes DLC 5 (query, D=0) or 7 (Ziel-UID, speed)");
}

Message functions(const can::CanFrame& frame) {
    const Data d{frame};
    if (d.size() == 3 && !d.answer())
        return LocoFunctionsQuery{originOf(frame), d.u16(1)};
    if (d.size() == 7)
        return LocoFunctions{originOf(frame), d.answer(), d.u16(1), d.u32(3)};
    return unknown(frame, "Lok Funktion 0x03 takes DLC 3 (query, D=0) or 7 (Ziel-Id, Fx0-Fx31)");
}

Message function(const can::CanFrame& frame) {
    const Data d{frame};
    if (d.size() == 4 && !d.answer())
        return LocoFunctionQuery{originOf(frame), d.u16(1), d[3]};
    if (d.size() > 7)
        return unknown(frame, "Lok Funktion 0x04 takes DLC 4 (query, D=0) or 5-7 (FxNr, Wert)");
    if (d.size() >= 5 && (d[5] != 0 || d[6] != 0))
        return unknown(frame, "Lok Funktion 0x04: Wert is one byte (DB5); DB6-7 must be 0");
    if (d.size() >= 5)
        return LocoFunction{originOf(frame), d.answer(), d.u16(1), d[3], d[4], std::uint8_t(d.size())};
    return unknown(frame, "Lok Funktion 0x04 takes DLC 4 (query, D=0) or 5-7 (FxNr, Wert)");
}

} // namespace

Message decodeSystem(const can::CanFrame& frame) {
    const Data d{frame};
    switch (d[0]) {
    case sub::AllOff:
        return systemSwitch(frame, false);
    case sub::AllOn:
        return systemSwitch(frame, true);
    case sub::Overload:
        if (d.size() == 2 || d.size() == 3)
            return Overload{originOf(frame), d.answer(), d[1], d.size() == 3, d[2]};
        return unknown(frame, "Ueberlast takes DLC 2 (type) or 3 (type, port)");
    default:
        break;
    }
    return unknown(frame, "a sub-command group 0x80 does not define");
}

Message decodeLoco(const can::CanFrame& frame) {
    switch (Data{frame}[0]) {
    case sub::LocoStop:
        return locoStop(frame);
    case sub::Speed:
        return speed(frame);
    case sub::SpeedByUid:
        return speedByUid(frame);
    case sub::Functions:
        return functions(frame);
    case sub::Function:
        return function(frame);
    default:
        break;
    }
    return unknown(frame, "a sub-command group 0x81 does not define");
}

can::CanFrame encodeOne(const AllOff& m) {
    Payload p;
    return frameOf(m.from, group::System, false, prio::Safety, putTarget(p.byte(sub::AllOff), m.target));
}
can::CanFrame encodeOne(const AllOn& m) {
    Payload p;
    return frameOf(m.from, group::System, false, prio::Safety, putTarget(p.byte(sub::AllOn), m.target));
}
can::CanFrame encodeOne(const Overload& m) {
    Payload p;
    p.byte(sub::Overload).byte(m.kind);
    if (m.hasPort)
        p.byte(m.port);
    return frameOf(m.from, group::System, m.answer, prio::Safety, p);
}
can::CanFrame encodeOne(const LocoStop& m) {
    Payload p;
    return frameOf(m.from, group::Loco, false, prio::Safety, putTarget(p.byte(sub::LocoStop), m.target));
}
can::CanFrame encodeOne(const LocoSpeedQuery& m) {
    return frameOf(m.from, group::Loco, false, prio::Control, Payload().byte(sub::Speed).u16(m.target));
}
can::CanFrame encodeOne(const LocoSpeed& m) {
    return frameOf(m.from, group::Loco, m.answer, prio::Control,
                   Payload().byte(sub::Speed).u16(m.target).u16(m.speed));
}
can::CanFrame encodeOne(const LocoSpeedQueryByUid& m) {
    return frameOf(m.from, group::Loco, false, prio::Control, Payload().byte(sub::SpeedByUid).u32(m.uid));
}
can::CanFrame encodeOne(const LocoSpeedByUid& m) {
    const std::uint8_t code = m.textForm ? sub::Speed : sub::SpeedByUid;
    return frameOf(m.from, group::Loco, m.answer, prio::Control,
                   Payload().byte(code).u32(m.uid).u16(m.speed));
}
can::CanFrame encodeOne(const LocoFunctionsQuery& m) {
    return frameOf(m.from, group::Loco, false, prio::Control, Payload().byte(sub::Functions).u16(m.target));
}
can::CanFrame encodeOne(const LocoFunctions& m) {
    return frameOf(m.from, group::Loco, m.answer, prio::Control,
                   Payload().byte(sub::Functions).u16(m.target).u32(m.functions));
}
can::CanFrame encodeOne(const LocoFunctionQuery& m) {
    return frameOf(m.from, group::Loco, false, prio::Control,
                   Payload().byte(sub::Function).u16(m.target).byte(m.function));
}
can::CanFrame encodeOne(const LocoFunction& m) {
    Payload p;
    p.byte(sub::Function).u16(m.target).byte(m.function).byte(m.value);
    for (std::uint8_t size = 5; size < m.dlc && size < 7; ++size)
        p.byte(0);
    return frameOf(m.from, group::Loco, m.answer, prio::Control, p);
}

} // namespace stellwerk::orc::detail
