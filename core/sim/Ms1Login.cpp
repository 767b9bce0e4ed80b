#include "sim/Ms1Login.h"

#include "mcan/Codec.h"

#include <array>

namespace stellwerk::sim {

namespace {

// Stages 5-7 as the trace's MS1 sends them (#12-#14): vendor 0x97, hardware 40.10, build 0x67, software 1.8.
constexpr std::array<std::array<std::uint8_t, 8>, 3> LaterDetails = {{
    {0x00, 0x00, 0x00, 0x97, 0x01, 0x00, 0x40, 0x10},
    {0x01, 0x00, 0x00, 0x67, 0x00, 0x00, 0x40, 0x10},
    {0x00, 0x00, 0x40, 0x10, 0x01, 0x08, 0x00, 0x10},
}};

// Stage 4: the whole UID and `00 02 00 03` (#11).
std::array<std::uint8_t, 8> uidDetails(std::uint32_t uid) {
    return {std::uint8_t(uid >> 24),
            std::uint8_t(uid >> 16),
            std::uint8_t(uid >> 8),
            std::uint8_t(uid),
            0x00,
            0x02,
            0x00,
            0x03};
}

} // namespace

can::CanFrame Ms1Login::start() {
    expecting_ = Expecting::Reply;
    stage_ = 0;
    mid_ = 0;
    return mcan::encode(mcan::LoginRequest{0, uidByte(0), 0});
}

// At stage 0 the MID is not known yet: a reply echoing another first byte is another MS1's, and the first
// one with ours hands out the MID. From stage 1 the MID says the reply is ours, and the byte whether we won.
Ms1Login::Outcome Ms1Login::onReply(const mcan::LoginReply& reply, std::vector<can::CanFrame>& out) {
    if (expecting_ != Expecting::Reply || reply.stage != stage_ || (stage_ > 0 && reply.mid != mid_))
        return Outcome::Ignored;
    if (reply.uidByte != uidByte(stage_)) {
        if (stage_ == 0)
            return Outcome::Ignored;
        stop();
        return Outcome::Lost;
    }
    if (stage_ == 0) {
        mid_ = reply.mid;
        masterType_ = reply.data[7];
    }
    if (stage_ == 3) {
        sendDetails(out);
        expecting_ = Expecting::Grant;
        return Outcome::Advanced;
    }
    ++stage_;
    out.push_back(mcan::encode(mcan::LoginRequest{stage_, uidByte(stage_), mid_}));
    return Outcome::Advanced;
}

void Ms1Login::sendDetails(std::vector<can::CanFrame>& out) const {
    out.push_back(mcan::encode(mcan::LoginDetails{4, mid_, uidDetails(uid_)}));
    for (std::uint8_t stage = 5; stage <= 7; ++stage)
        out.push_back(mcan::encode(mcan::LoginDetails{stage, mid_, LaterDetails[stage - 5]}));
}

Ms1Login::Outcome Ms1Login::onGrant(const mcan::LoginGrant& grant) {
    if (expecting_ != Expecting::Grant || grant.mid != mid_ || grant.slaveUid != uid_)
        return Outcome::Ignored;
    stop();
    grant_ = grant;
    return (grant.flags & 0x01) != 0 ? Outcome::FlashMode : Outcome::Granted;
}

} // namespace stellwerk::sim
