#include "mcan/CodecDetail.h"

#include <algorithm>

// The login layout (node 126, document 6.2), and the Unknown message every layout falls back to.

namespace stellwerk::mcan::detail {
namespace {

Message loginFromSlave(const can::CanFrame& frame, const LoginId& login) {
    if (login.stage <= 3) {
        if (frame.dlc != 0)
            return unknown(frame, "login stages 0-3 of a slave carry no data");
        return LoginRequest{login.stage, login.uidByte, login.mid};
    }
    if (frame.dlc != 8 || login.uidByte != 0)
        return unknown(frame, "login stages 4-7 of a slave have 8 data bytes and no UID byte in the id");
    LoginDetails details{login.stage, login.mid, {}};
    std::copy_n(frame.data.begin(), 8, details.data.begin());
    return details;
}

Message loginFromMaster(const can::CanFrame& frame, const LoginId& login) {
    if (frame.dlc != 8)
        return unknown(frame, "a master's login reply has 8 data bytes");
    if (login.stage <= 3) {
        LoginReply reply{login.stage, login.uidByte, login.mid, {}};
        std::copy_n(frame.data.begin(), 8, reply.data.begin());
        return reply;
    }
    if (login.stage != 7 || login.uidByte != 0)
        return unknown(frame, "a master answers login stages 0-3 and 7 only");
    const Data d{frame};
    return LoginGrant{login.mid, d.u32(0), d.u16(4), std::uint8_t(d[6] & 0x7F), (d[6] & 0x80) != 0, d[7]};
}

std::uint32_t loginFrameId(std::uint8_t stage, std::uint8_t uidByte, std::uint8_t mid, bool master) {
    return loginId({uidByte, stage, mid, master});
}

} // namespace

Unknown unknown(const can::CanFrame& frame, std::string_view why) {
    Unknown result{frame.id, {std::uint8_t(frame.size()), {}}, why};
    std::copy_n(frame.data.begin(), frame.size(), result.payload.data.begin());
    if (frame.dlc > 8)
        result.payload.size = 8;
    return result;
}

Message decodeLogin(const can::CanFrame& frame) {
    if ((frame.id & 0x300) != 0)
        return unknown(frame, "login ids keep bits 9-8 clear");
    const LoginId login = readLogin(frame.id);
    return login.fromMaster ? loginFromMaster(frame, login) : loginFromSlave(frame, login);
}

can::CanFrame encodeOne(const LoginRequest& m) {
    return Payload().frame(loginFrameId(m.stage, m.uidByte, m.mid, false));
}

can::CanFrame encodeOne(const LoginReply& m) {
    Payload payload;
    for (const std::uint8_t byte : m.data)
        payload.byte(byte);
    return payload.frame(loginFrameId(m.stage, m.uidByte, m.mid, true));
}

can::CanFrame encodeOne(const LoginDetails& m) {
    Payload payload;
    for (const std::uint8_t byte : m.data)
        payload.byte(byte);
    return payload.frame(loginFrameId(m.stage, 0, m.mid, false));
}

can::CanFrame encodeOne(const LoginGrant& m) {
    return Payload()
        .u32(m.slaveUid)
        .u16(m.startHandle)
        .byte(std::uint8_t((m.node & 0x7F) | (m.multiSlave ? 0x80 : 0)))
        .byte(m.flags)
        .frame(loginFrameId(7, 0, m.mid, true));
}

can::CanFrame encodeOne(const Unknown& m) {
    return can::CanFrame::extendedFrame(m.id,
                                        std::span<const std::uint8_t>(m.payload.data.data(), m.payload.size));
}

} // namespace stellwerk::mcan::detail
