#include "mcan/CodecDetail.h"

// Session frames about status values, functions, the locomotive's assignment and the cyclic monitoring
// (cmd 010, 000, 111; document 6.6, 6.7.3, 6.7.5, 7.2, 7.6) and the bus-busy frame (6.1).

namespace stellwerk::mcan::detail {
namespace {

// A list frame is about the status list on the SY handle and about functions on a locomotive's handle;
// without knowing the handle, the status priority 100 says "status".
bool isStatus(const can::CanFrame& frame, HandleRole role) {
    if (role == HandleRole::SystemStatus)
        return true;
    if (role == HandleRole::Loco)
        return false;
    return readSession(frame.id).prio == prio::Status;
}

Message decodeStatus(const can::CanFrame& frame, const Address& at, bool master) {
    const Data d{frame};
    const std::size_t n = d.size();
    if (n == 2 && !master && (d[1] == 0 || d[1] == 1))
        return StatusQuery{at, d[0], d[1] == 1};
    if (n == 2 && master && d[1] == 1)
        return StatusListEnd{at, d[0]};
    if (n == 3 && master && d[1] == 1)
        return StatusType{at, d[0], d[2]};
    if (n == 3 && d[1] == 0)
        return StatusValue{at, d[0], d[2]};
    return unknown(frame, "status frame without a documented form");
}

Message decodeFunction(const can::CanFrame& frame, const Address& at, bool master) {
    const Data d{frame};
    const std::size_t n = d.size();
    if (n == 2 && !master && (d[1] == 0 || d[1] == 1))
        return FunctionQuery{at, d[0], d[1] == 1};
    if (n == 2 && master && d[1] == 1)
        return FunctionListEnd{at, d[0]};
    if (n == 4 && master && d[1] == 1)
        return FunctionDescription{at, d[0], d[2], d[3]};
    if (n == 3 && d[1] == 0)
        return FunctionValue{at, d[0], d[2]};
    return unknown(frame, "function frame without a documented form");
}

} // namespace

Message decodeList(const can::CanFrame& frame, HandleRole role) {
    const Data d{frame};
    const Address at = addressOf(frame);
    const bool master = fromMaster(frame);
    if (d[0] == 0x01 && d[1] == 0x02 && d[3] == 0 && d.size() == 4 && !master)
        return FunctionExtraQuery{at, d[2]};
    if (d[0] == 0x01 && d[1] == 0x02 && d[3] == 0 && d.size() == 5 && master)
        return FunctionExtraAnswer{at, d[2], d[4]};
    return isStatus(frame, role) ? decodeStatus(frame, at, master) : decodeFunction(frame, at, master);
}

Message decodeState(const can::CanFrame& frame) {
    const Data d{frame};
    const Address at = addressOf(frame);
    if (d.size() == 2 && d[0] == 0x03 && d[1] == 0 && !fromMaster(frame))
        return AssignmentQuery{at};
    if (d.size() == 6 && d[0] == 0x03 && d[4] == 0)
        return Throttle{at, d[1], d.u16(2), d[5]};
    return unknown(frame, "cmd 000 without a documented form");
}

Message decodeMonitor(const can::CanFrame& frame) {
    const Data d{frame};
    const Address at = addressOf(frame);
    const bool master = fromMaster(frame);
    if (frame.id == BusBusyId && d.zeros(0, d.size()))
        return BusBusy{std::uint8_t(d.size())};
    if (d.size() == 4 && d.zeros(0, 3))
        return master ? Message(MasterPoll{at, d[3]}) : Message(Poll{at, d[3]});
    if (d.size() == 8 && master && d.zeros(1, 3))
        return PollAnswer{at, d[0], d[3], d.u32(4)};
    if (d.size() == 8 && !master && d[0] == 0x03 && d.zeros(1, 4))
        return PollReply{at, d.u32(4)};
    return unknown(frame, "cmd 111 without a documented form");
}

can::CanFrame encodeOne(const StatusQuery& m) {
    return sessionFrame(m.at, cmd::List, Payload().bytes({m.index, std::uint8_t(m.type ? 1 : 0)}));
}

can::CanFrame encodeOne(const StatusType& m) {
    return sessionFrame(m.at, cmd::List, Payload().bytes({m.index, 1, m.type}));
}

can::CanFrame encodeOne(const StatusListEnd& m) {
    return sessionFrame(m.at, cmd::List, Payload().bytes({m.index, 1}));
}

can::CanFrame encodeOne(const StatusValue& m) {
    return sessionFrame(m.at, cmd::List, Payload().bytes({m.index, 0, m.value}));
}

can::CanFrame encodeOne(const FunctionQuery& m) {
    return sessionFrame(m.at, cmd::List, Payload().bytes({m.function, std::uint8_t(m.description ? 1 : 0)}));
}

can::CanFrame encodeOne(const FunctionDescription& m) {
    return sessionFrame(m.at, cmd::List, Payload().bytes({m.function, 1, m.kind, m.icon}));
}

can::CanFrame encodeOne(const FunctionListEnd& m) {
    return sessionFrame(m.at, cmd::List, Payload().bytes({m.function, 1}));
}

can::CanFrame encodeOne(const FunctionValue& m) {
    return sessionFrame(m.at, cmd::List, Payload().bytes({m.function, 0, m.value}));
}

can::CanFrame encodeOne(const FunctionExtraQuery& m) {
    return sessionFrame(m.at, cmd::List, Payload().bytes({0x01, 0x02, m.n, 0}));
}

can::CanFrame encodeOne(const FunctionExtraAnswer& m) {
    return sessionFrame(m.at, cmd::List, Payload().bytes({0x01, 0x02, m.n, 0, m.value}));
}

can::CanFrame encodeOne(const AssignmentQuery& m) {
    return sessionFrame(m.at, cmd::State, Payload().bytes({0x03, 0}));
}

can::CanFrame encodeOne(const Throttle& m) {
    return sessionFrame(m.at, cmd::State,
                        Payload().bytes({0x03, m.control}).u16(m.state).bytes({0, m.extra}));
}

can::CanFrame encodeOne(const BusBusy& m) {
    Payload payload;
    for (std::uint8_t i = 0; i < m.dlc && i < 8; ++i)
        payload.byte(0);
    return payload.frame(BusBusyId);
}

can::CanFrame encodeOne(const Poll& m) {
    return sessionFrame(m.at, cmd::Monitor, Payload().bytes({0, 0, 0, m.masterNode}));
}

can::CanFrame encodeOne(const PollAnswer& m) {
    return sessionFrame(m.at, cmd::Monitor, Payload().bytes({m.lead, 0, 0, m.aboutNode}).u32(m.uid));
}

can::CanFrame encodeOne(const MasterPoll& m) {
    return sessionFrame(m.at, cmd::Monitor, Payload().bytes({0, 0, 0, m.aboutNode}));
}

can::CanFrame encodeOne(const PollReply& m) {
    return sessionFrame(m.at, cmd::Monitor, Payload().bytes({0x03, 0, 0, 0}).u32(m.uid));
}

} // namespace stellwerk::mcan::detail
