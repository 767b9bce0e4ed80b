#include "orc/CodecDetail.h"

// Groups 0x90 System Management and 0xF0 Programm Flash (001 §Befehlssatz, l. 1710-2249; notes A2 #30-#42),
// with Stellwerk's bus-id extension (notes A3.2): the answer to Find and the assignment, marked EXTENSION.

namespace stellwerk::orc::detail {
namespace {

namespace sub {
inline constexpr std::uint8_t Ping = 0x00;
inline constexpr std::uint8_t Find = 0x01;
inline constexpr std::uint8_t Assign = 0x02; // EXTENSION: unused in group 0x90 by the document
inline constexpr std::uint8_t Cancel = 0x00;
inline constexpr std::uint8_t Init = 0x01;
inline constexpr std::uint8_t Size = 0x02;     // the heading's code (the table prints 0x01)
inline constexpr std::uint8_t Data = 0x04;     // data
inline constexpr std::uint8_t Checksum = 0x05; // the heading's code (the table prints 0x04)
} // namespace sub

Message flashInit(const can::CanFrame& frame) {
    const Data d{frame};
    const Origin from = originOf(frame);
    if (!d.answer() && d.size() == 4)
        return FlashInit{from, Target::busId(d.u16(1)), d[3]};
    if (!d.answer() && d.size() == 6)
        return FlashInit{from, Target::uid(d.u32(1)), d[5]};
    if (d.answer() && d.size() == 8)
        return FlashAccepted{from, d.u16(1), d.u32(3), d[7]};
    if (!d.answer() && d.size() == 8)
        return FlashSize{from, d.u16(1), d.u24(3), d.u16(6), true};
    if (d.answer() && d.size() == 6)
        return FlashSizeAnswer{from, d.u16(1), d.u16(3), d[5], true};
    return unknown(frame, "Flash INIT takes DLC 4 or 6 (D=0); Flash Acceppted DLC 8 (D=1)");
}

Message flashSize(const can::CanFrame& frame) {
    const Data d{frame};
    if (!d.answer() && d.size() == 8)
        return FlashSize{originOf(frame), d.u16(1), d.u24(3), d.u16(6), false};
    if (d.answer() && d.size() == 6)
        return FlashSizeAnswer{originOf(frame), d.u16(1), d.u16(3), d[5], false};
    return unknown(frame, "Flash Size takes DLC 8 (D=0) or 6 (D=1)");
}

Message flashTransfer(const can::CanFrame& frame) {
    const Data d{frame};
    if (d.size() != 8)
        return unknown(frame, "Flash Data and Checksum take DLC 8");
    if (d[0] == sub::Checksum)
        return FlashChecksum{originOf(frame), d.answer(), d.u16(1), d[3], d.u32(4)};
    return FlashData{originOf(frame), d.answer(), d.u16(1), d[3], {d[4], d[5], d[6], d[7]}};
}

} // namespace

Message decodeManagement(const can::CanFrame& frame) {
    const Data d{frame};
    const Origin from = originOf(frame);
    if (d[0] == sub::Ping && !d.answer() && d.size() == 5)
        return Ping{from, d.u32(1)};
    if (d[0] == sub::Ping && d.answer() && d.size() == 7)
        return PingAnswer{from, d.u32(1), d.u16(5)};
    if (d[0] == sub::Find && !d.answer() && d.size() == 5)
        return Find{from, d.u32(1)};
    if (d[0] == sub::Find && d.answer() && d.size() == 7)
        return FindAnswer{from, d.u32(1), d.u16(5)};
    if (d[0] == sub::Assign && d.size() == 7)
        return AssignBusId{from, d.answer(), d.u32(1), d.u16(5)};
    if (d[0] <= sub::Assign)
        return unknown(frame, "Ping / Find take DLC 5 (D=0) or 7 (D=1); the bus-id assignment DLC 7");
    return unknown(frame, "a sub-command group 0x90 does not define");
}

Message decodeFlash(const can::CanFrame& frame) {
    const Data d{frame};
    switch (d[0]) {
    case sub::Cancel:
        if (d.size() == 1 && !d.answer())
            return FlashCancel{originOf(frame)};
        return unknown(frame, "Flash Cancel takes DLC 1 with D=0");
    case sub::Init:
        return flashInit(frame);
    case sub::Size:
        return flashSize(frame);
    case sub::Data:
    case sub::Checksum:
        return flashTransfer(frame);
    default:
        break;
    }
    return unknown(frame, "a sub-command group 0xF0 does not define");
}

can::CanFrame encodeOne(const Ping& m) {
    return frameOf(m.from, group::Management, false, prio::Management, Payload().byte(sub::Ping).u32(m.uid));
}
can::CanFrame encodeOne(const PingAnswer& m) {
    return frameOf(m.from, group::Management, true, prio::Management,
                   Payload().byte(sub::Ping).u32(m.uid).u16(m.version));
}
can::CanFrame encodeOne(const Find& m) {
    return frameOf(m.from, group::Management, false, prio::Management, Payload().byte(sub::Find).u32(m.uid));
}
can::CanFrame encodeOne(const FindAnswer& m) {
    return frameOf(m.from, group::Management, true, prio::Management,
                   Payload().byte(sub::Find).u32(m.uid).u16(m.version));
}
can::CanFrame encodeOne(const AssignBusId& m) {
    return frameOf(m.from, group::Management, m.answer, prio::Management,
                   Payload().byte(sub::Assign).u32(m.uid).u16(m.busId));
}
can::CanFrame encodeOne(const FlashCancel& m) {
    return frameOf(m.from, group::Flash, false, prio::Management, Payload().byte(sub::Cancel));
}
can::CanFrame encodeOne(const FlashInit& m) {
    Payload p;
    putTarget(p.byte(sub::Init), m.target).byte(m.version);
    return frameOf(m.from, group::Flash, false, prio::Management, p);
}
can::CanFrame encodeOne(const FlashAccepted& m) {
    return frameOf(m.from, group::Flash, true, prio::Management,
                   Payload().byte(sub::Init).u16(m.target).u32(m.uid).byte(m.version));
}
can::CanFrame encodeOne(const FlashSize& m) {
    const std::uint8_t code = m.tableCode ? sub::Init : sub::Size;
    return frameOf(m.from, group::Flash, false, prio::Management,
                   Payload().byte(code).u16(m.target).u24(m.start).u16(m.size));
}
can::CanFrame encodeOne(const FlashSizeAnswer& m) {
    const std::uint8_t code = m.tableCode ? sub::Init : sub::Size;
    return frameOf(m.from, group::Flash, true, prio::Management,
                   Payload().byte(code).u16(m.target).u16(m.available).byte(m.countMax));
}
can::CanFrame encodeOne(const FlashData& m) {
    Payload p;
    p.byte(sub::Data).u16(m.target).byte(m.count);
    for (const std::uint8_t byte : m.bytes)
        p.byte(byte);
    return frameOf(m.from, group::Flash, m.answer, prio::Management, p);
}
can::CanFrame encodeOne(const FlashChecksum& m) {
    return frameOf(m.from, group::Flash, m.answer, prio::Management,
                   Payload().byte(sub::Checksum).u16(m.target).byte(m.count).u32(m.crc));
}

} // namespace stellwerk::orc::detail
