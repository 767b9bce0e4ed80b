#include "mcan/CodecDetail.h"

// Session frames about handles, names, the locomotive stack and a locomotive's properties (cmd 100, 101,
// 001, 011; document 6.4 to 6.7 and 7.7).

namespace stellwerk::mcan::detail {
namespace {

bool isLocoList(std::uint8_t list) {
    return list == 0x80 || list == 0x81 || list == 0x82;
}

Message decodeHandle(const can::CanFrame& frame, const Address& at, bool master) {
    const Data d{frame};
    if (!master && d.size() == 2 && d[0] == 0x40)
        return SdHandleRequest{at, d[1]};
    if (master && d.size() == 8 && d[0] == 0x40 && d.zeros(2, 4) && d[6] == 0 && d[7] == 1)
        return SdHandleAnswer{at, d[1], d.u16(4)};
    if (master && d.size() == 8 && d[0] == 0x80 && d[1] == 0 && d.u16(2) == 0xFFFF && d[6] == 0 && d[7] == 3)
        return StackAdd{at, d.u16(4)};
    return unknown(frame, "cmd 100 without a documented form");
}

Message decodeDelete(const can::CanFrame& frame, const Address& at, bool master) {
    const Data d{frame};
    if (master && d.size() == 8 && d[0] == 0x80 && d.zeros(1, 4) && d[6] == 0 && d[7] == 1)
        return StackDelete{at, d.u16(4)};
    return unknown(frame, "cmd 101 without a documented form");
}

Message decodeNameSegment(const can::CanFrame& frame, const Address& at) {
    const Data d{frame};
    NameSegment segment{at, d[3], std::uint8_t(d.size() - 4), {}, d[1]};
    for (std::size_t i = 0; i < segment.count; ++i)
        segment.chars[i] = char(d[4 + i]);
    return segment;
}

Message decodeName(const can::CanFrame& frame, const Address& at, bool master) {
    const Data d{frame};
    const std::size_t n = d.size();
    if (d[0] == 0x41 && d.zeros(1, 4) && n == 4 && master)
        return StackSizeRequest{at};
    if (d[0] == 0x41 && d.zeros(1, 4) && n == 6 && !master)
        return StackSizeAnswer{at, d.u16(4)};
    if (d[0] == 0x02 && d[2] == 0 && n == 4 && d[1] == 0)
        return NameRequest{at, d[3]};
    if (d[0] == 0x02 && d[2] == 0 && n >= 5)
        return decodeNameSegment(frame, at);
    const bool loco = d[0] == 0x40 && (d[1] == 0x01 || d[1] == 0x03 || d[1] == 0x04) && d[3] == 0;
    if (loco && n == 4 && !master)
        return LocoQuery{at, d[1], d[2]};
    if (loco && n >= 5 && master) {
        LocoAnswer answer{at, d[1], d[2], {std::uint8_t(n - 4), {}}};
        for (std::size_t i = 4; i < n; ++i)
            answer.tail.data[i - 4] = d[i];
        return answer;
    }
    return unknown(frame, "cmd 001 without a documented form");
}

Message decodeObject(const can::CanFrame& frame, const Address& at, bool master) {
    const Data d{frame};
    const std::size_t n = d.size();
    if (!master && n == 2 && d[0] == 0x03 && d[1] == 0)
        return SyHandleRequest{at};
    if (master && n == 8 && (d[0] == 0x03 || d[0] == 0x40) && d.zeros(2, 4) && d[6] == 0 && d[7] == 1)
        return SyHandleAnswer{at, d.u16(4), d[0], d[1]};
    if (isLocoList(d[0]) && d[1] == 0x02 && n == 4)
        return master ? Message(LocoListEnd{at, d[0], d.u16(2)}) : Message(LocoListQuery{at, d[0], d.u16(2)});
    if (isLocoList(d[0]) && d[1] == 0x02 && n == 8 && master && d[6] == 0 && d[7] == 1)
        return LocoListAnswer{at, d[0], d.u16(2), d.u16(4)};
    return unknown(frame, "cmd 011 without a documented form");
}

} // namespace

Message decodeSession(const can::CanFrame& frame, HandleRole role) {
    const SessionId s = readSession(frame.id);
    const Address at = addressOf(frame);
    const bool master = fromMaster(frame);
    switch (s.cmd) {
    case cmd::Handle:
        return decodeHandle(frame, at, master);
    case cmd::Delete:
        return decodeDelete(frame, at, master);
    case cmd::Name:
        return decodeName(frame, at, master);
    case cmd::Object:
        return decodeObject(frame, at, master);
    case cmd::List:
        return decodeList(frame, role);
    case cmd::State:
        return decodeState(frame);
    case cmd::Monitor:
        return decodeMonitor(frame);
    default:
        break;
    }
    return unknown(frame, "cmd 110 is the CS2's marker, never M-CAN");
}

can::CanFrame encodeOne(const SdHandleRequest& m) {
    return sessionFrame(m.at, cmd::Handle, Payload().bytes({0x40, m.slaveNode}));
}

can::CanFrame encodeOne(const SdHandleAnswer& m) {
    return sessionFrame(m.at, cmd::Handle,
                        Payload().bytes({0x40, m.slaveNode, 0, 0}).u16(m.sdHandle).bytes({0, 1}));
}

can::CanFrame encodeOne(const StackAdd& m) {
    return sessionFrame(m.at, cmd::Handle,
                        Payload().bytes({0x80, 0, 0xFF, 0xFF}).u16(m.locoHandle).bytes({0, 3}));
}

can::CanFrame encodeOne(const StackDelete& m) {
    return sessionFrame(m.at, cmd::Delete, Payload().bytes({0x80, 0, 0, 0}).u16(m.locoHandle).bytes({0, 1}));
}

can::CanFrame encodeOne(const StackSizeRequest& m) {
    return sessionFrame(m.at, cmd::Name, Payload().bytes({0x41, 0, 0, 0}));
}

can::CanFrame encodeOne(const StackSizeAnswer& m) {
    return sessionFrame(m.at, cmd::Name, Payload().bytes({0x41, 0, 0, 0}).u16(m.size));
}

can::CanFrame encodeOne(const NameRequest& m) {
    return sessionFrame(m.at, cmd::Name, Payload().bytes({0x02, 0, 0, m.offset}));
}

can::CanFrame encodeOne(const NameSegment& m) {
    Payload payload;
    payload.bytes({0x02, m.marker, 0, m.offset});
    for (std::uint8_t i = 0; i < m.count && i < 4; ++i)
        payload.byte(std::uint8_t(m.chars[i]));
    return sessionFrame(m.at, cmd::Name, payload);
}

can::CanFrame encodeOne(const LocoQuery& m) {
    return sessionFrame(m.at, cmd::Name, Payload().bytes({0x40, m.what, m.variant, 0}));
}

can::CanFrame encodeOne(const LocoAnswer& m) {
    Payload payload;
    payload.bytes({0x40, m.what, m.variant, 0});
    for (std::uint8_t i = 0; i < m.tail.size && i < 4; ++i)
        payload.byte(m.tail.data[i]);
    return sessionFrame(m.at, cmd::Name, payload);
}

can::CanFrame encodeOne(const SyHandleRequest& m) {
    return sessionFrame(m.at, cmd::Object, Payload().bytes({0x03, 0}));
}

can::CanFrame encodeOne(const SyHandleAnswer& m) {
    return sessionFrame(m.at, cmd::Object,
                        Payload().bytes({m.lead, m.second, 0, 0}).u16(m.syHandle).bytes({0, 1}));
}

can::CanFrame encodeOne(const LocoListQuery& m) {
    return sessionFrame(m.at, cmd::Object, Payload().bytes({m.list, 0x02}).u16(m.previous));
}

can::CanFrame encodeOne(const LocoListAnswer& m) {
    return sessionFrame(m.at, cmd::Object,
                        Payload().bytes({m.list, 0x02}).u16(m.previous).u16(m.next).bytes({0, 1}));
}

can::CanFrame encodeOne(const LocoListEnd& m) {
    return sessionFrame(m.at, cmd::Object, Payload().bytes({m.list, 0x02}).u16(m.previous));
}

} // namespace stellwerk::mcan::detail
