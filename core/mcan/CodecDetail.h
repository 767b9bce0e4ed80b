#pragma once

// Shared by the M-CAN codec's files only: reading bytes, building frames, and one decode and encode
// function per message group.

#include "can/CanFrame.h"
#include "mcan/Codec.h"

#include <array>
#include <cstdint>
#include <initializer_list>
#include <span>

namespace stellwerk::mcan::detail {

// The data bytes of a frame, read safely: a byte beyond the DLC reads as 0.
struct Data {
    const can::CanFrame& frame;
    std::size_t size() const { return frame.size(); }
    std::uint8_t operator[](std::size_t i) const { return i < frame.size() ? frame.data[i] : 0; }
    std::uint16_t u16(std::size_t i) const { return std::uint16_t((*this)[i] << 8 | (*this)[i + 1]); }
    std::uint32_t u32(std::size_t i) const { return std::uint32_t(u16(i)) << 16 | u16(i + 2); }
    // Whether bytes [from, to) are all zero.
    bool zeros(std::size_t from, std::size_t to) const {
        for (std::size_t i = from; i < to; ++i)
            if ((*this)[i] != 0)
                return false;
        return true;
    }
};

Unknown unknown(const can::CanFrame& frame, std::string_view why);

// Builds a frame's payload byte by byte.
class Payload {
public:
    Payload& byte(std::uint8_t value) {
        if (size_ < 8)
            bytes_[size_++] = value;
        return *this;
    }
    Payload& bytes(std::initializer_list<std::uint8_t> values) {
        for (const std::uint8_t value : values)
            byte(value);
        return *this;
    }
    Payload& u16(std::uint16_t value) { return byte(std::uint8_t(value >> 8)).byte(std::uint8_t(value)); }
    Payload& u32(std::uint32_t value) { return u16(std::uint16_t(value >> 16)).u16(std::uint16_t(value)); }
    can::CanFrame frame(std::uint32_t id) const {
        return can::CanFrame::extendedFrame(id, std::span<const std::uint8_t>(bytes_.data(), size_));
    }

private:
    std::array<std::uint8_t, 8> bytes_{};
    std::size_t size_ = 0;
};

// A session frame of message type `cmd` from the address.
inline can::CanFrame sessionFrame(const Address& at, std::uint8_t command, const Payload& payload) {
    return payload.frame(sessionId({at.prio, at.handle, command, at.node}));
}
inline Address addressOf(const can::CanFrame& frame) {
    const SessionId s = readSession(frame.id);
    return {s.prio, s.handle, s.node};
}

Message decodeLogin(const can::CanFrame& frame);
Message decodeFlash(const can::CanFrame& frame);
Message decodeSession(const can::CanFrame& frame, HandleRole role);
Message decodeList(const can::CanFrame& frame, HandleRole role);
Message decodeState(const can::CanFrame& frame);
Message decodeMonitor(const can::CanFrame& frame);

can::CanFrame encodeOne(const LoginRequest& m);
can::CanFrame encodeOne(const LoginReply& m);
can::CanFrame encodeOne(const LoginDetails& m);
can::CanFrame encodeOne(const LoginGrant& m);
can::CanFrame encodeOne(const BusBusy& m);
can::CanFrame encodeOne(const SdHandleRequest& m);
can::CanFrame encodeOne(const SdHandleAnswer& m);
can::CanFrame encodeOne(const StackSizeRequest& m);
can::CanFrame encodeOne(const StackSizeAnswer& m);
can::CanFrame encodeOne(const NameRequest& m);
can::CanFrame encodeOne(const NameSegment& m);
can::CanFrame encodeOne(const SyHandleRequest& m);
can::CanFrame encodeOne(const SyHandleAnswer& m);
can::CanFrame encodeOne(const StatusQuery& m);
can::CanFrame encodeOne(const StatusType& m);
can::CanFrame encodeOne(const StatusListEnd& m);
can::CanFrame encodeOne(const StatusValue& m);
can::CanFrame encodeOne(const LocoListQuery& m);
can::CanFrame encodeOne(const LocoListAnswer& m);
can::CanFrame encodeOne(const LocoListEnd& m);
can::CanFrame encodeOne(const StackAdd& m);
can::CanFrame encodeOne(const StackDelete& m);
can::CanFrame encodeOne(const LocoQuery& m);
can::CanFrame encodeOne(const LocoAnswer& m);
can::CanFrame encodeOne(const FunctionQuery& m);
can::CanFrame encodeOne(const FunctionDescription& m);
can::CanFrame encodeOne(const FunctionListEnd& m);
can::CanFrame encodeOne(const FunctionValue& m);
can::CanFrame encodeOne(const FunctionExtraQuery& m);
can::CanFrame encodeOne(const FunctionExtraAnswer& m);
can::CanFrame encodeOne(const AssignmentQuery& m);
can::CanFrame encodeOne(const Throttle& m);
can::CanFrame encodeOne(const Poll& m);
can::CanFrame encodeOne(const PollAnswer& m);
can::CanFrame encodeOne(const MasterPoll& m);
can::CanFrame encodeOne(const PollReply& m);
can::CanFrame encodeOne(const FlashReady& m);
can::CanFrame encodeOne(const FlashQuery& m);
can::CanFrame encodeOne(const FlashAnswer& m);
can::CanFrame encodeOne(const FlashStart& m);
can::CanFrame encodeOne(const FlashDataRequest& m);
can::CanFrame encodeOne(const FlashData& m);
can::CanFrame encodeOne(const FlashEnd& m);
can::CanFrame encodeOne(const Unknown& m);

} // namespace stellwerk::mcan::detail
