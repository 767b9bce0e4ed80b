#include "orc/CodecDetail.h"

// Groups 0x88 Dekoder and 0x89 Enkoder: stationary outputs and inputs (001 §Befehlssatz, l. 1198-1706;
// notes A2 #21-#29).

namespace stellwerk::orc::detail {
namespace {

namespace sub {
inline constexpr std::uint8_t Restore = 0x02;
inline constexpr std::uint8_t Switch = 0x03;
inline constexpr std::uint8_t Status = 0x10;
} // namespace sub

std::optional<GroupAction> groupAction(const Data& d) {
    if (d.size() != 1 || d.answer() || d[0] > sub::Restore)
        return std::nullopt;
    return GroupAction(d[0]);
}

Message encoderStatus(const can::CanFrame& frame) {
    const Data d{frame};
    if (d.size() == 1 && !d.answer())
        return EncoderQuery{originOf(frame), true, 0};
    if (d.size() == 3 && !d.answer())
        return EncoderQuery{originOf(frame), false, d.u16(1)};
    if (d.size() < 4)
        return unknown(frame, "enkoder Abfrage takes DLC 1 or 3 with D=0");
    if (d.size() > 7)
        return unknown(frame, "enkoder Status takes DLC 4 to 7 (status 0 ... 31)");
    EncoderStatus status{originOf(frame), d.answer(), d.u16(1), std::uint8_t(d.size() - 3), 0};
    for (std::size_t i = 3; i < d.size(); ++i)
        status.inputs |= std::uint32_t(d[i]) << (8 * (i - 3));
    return status;
}

} // namespace

Message decodeDecoder(const can::CanFrame& frame) {
    const Data d{frame};
    if (const std::optional<GroupAction> action = groupAction(d))
        return AllDecoders{originOf(frame), *action};
    if (d[0] == sub::Switch && d.size() == 4)
        return DecoderSwitch{originOf(frame), d.answer(), d.u16(1), d[3]};
    if (d[0] <= sub::Restore)
        return unknown(frame, "Alle dekoder aus/EIN/Restore take DLC 1 with D=0");
    if (d[0] == sub::Switch)
        return unknown(frame, "dekoder schalten takes DLC 4 (Ziel-Id, Pos)");
    return unknown(frame, "a sub-command group 0x88 does not define");
}

Message decodeEncoder(const can::CanFrame& frame) {
    const Data d{frame};
    if (const std::optional<GroupAction> action = groupAction(d))
        return AllEncoders{originOf(frame), *action};
    if (d[0] <= sub::Restore)
        return unknown(frame, "Alle enkoder aus/ein/restore take DLC 1 with D=0");
    if (d[0] == sub::Status)
        return encoderStatus(frame);
    return unknown(frame, "a sub-command group 0x89 does not define");
}

can::CanFrame encodeOne(const AllDecoders& m) {
    return frameOf(m.from, group::Decoder, false, prio::Control, Payload().byte(std::uint8_t(m.action)));
}
can::CanFrame encodeOne(const DecoderSwitch& m) {
    return frameOf(m.from, group::Decoder, m.answer, prio::Control,
                   Payload().byte(sub::Switch).u16(m.target).byte(m.position));
}
can::CanFrame encodeOne(const AllEncoders& m) {
    return frameOf(m.from, group::Encoder, false, prio::Control, Payload().byte(std::uint8_t(m.action)));
}
can::CanFrame encodeOne(const EncoderQuery& m) {
    Payload p;
    p.byte(sub::Status);
    if (!m.everyEncoder)
        p.u16(m.target);
    return frameOf(m.from, group::Encoder, false, prio::Control, p);
}
can::CanFrame encodeOne(const EncoderStatus& m) {
    Payload p;
    p.byte(sub::Status).u16(m.encoder);
    for (std::uint8_t i = 0; i < m.bytes && i < 4; ++i)
        p.byte(std::uint8_t(m.inputs >> (8 * i)));
    return frameOf(m.from, group::Encoder, m.answer, prio::Control, p);
}

} // namespace stellwerk::orc::detail
