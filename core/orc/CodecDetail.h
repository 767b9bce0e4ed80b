#pragma once

// Shared by the ORC codec's files only: reading bytes, building frames, one decode function per command
// group and one encode function per message.

#include "can/CanFrame.h"
#include "orc/Codec.h"

#include <array>
#include <cstdint>
#include <optional>
#include <span>

namespace stellwerk::orc::detail {

// The data bytes of a frame, read safely (a byte beyond the DLC reads as 0), big endian (notes A1.5).
struct Data {
    const can::CanFrame& frame;
    std::size_t size() const { return frame.size(); }
    std::uint8_t operator[](std::size_t i) const { return i < frame.size() ? frame.data[i] : 0; }
    std::uint16_t u16(std::size_t i) const { return std::uint16_t((*this)[i] << 8 | (*this)[i + 1]); }
    std::uint32_t u24(std::size_t i) const { return std::uint32_t((*this)[i]) << 16 | u16(i + 1); }
    std::uint32_t u32(std::size_t i) const { return std::uint32_t(u16(i)) << 16 | u16(i + 2); }
    bool answer() const { return readId(frame.id).answer; }
};

// Builds a frame's payload, big endian.
class Payload {
public:
    Payload& byte(std::uint8_t value) {
        if (size_ < 8)
            bytes_[size_++] = value;
        return *this;
    }
    Payload& u16(std::uint16_t value) { return byte(std::uint8_t(value >> 8)).byte(std::uint8_t(value)); }
    Payload& u24(std::uint32_t value) { return byte(std::uint8_t(value >> 16)).u16(std::uint16_t(value)); }
    Payload& u32(std::uint32_t value) { return u16(std::uint16_t(value >> 16)).u16(std::uint16_t(value)); }
    can::CanFrame frame(std::uint32_t id) const {
        return can::CanFrame::extendedFrame(id, std::span<const std::uint8_t>(bytes_.data(), size_));
    }

private:
    std::array<std::uint8_t, 8> bytes_{};
    std::size_t size_ = 0;
};

Origin originOf(const can::CanFrame& frame);
Unknown unknown(const can::CanFrame& frame, std::string_view why);
// DLC 1 / 3 / 5 after the sub-command: everybody, a Ziel-Id, a Ziel-UID.
std::optional<Target> targetOf(const Data& d);
Payload& putTarget(Payload& payload, const Target& target);

// The frame of a message of `group` with direction `answer` from `from`; priority 0 = `fallbackPrio`.
can::CanFrame frameOf(const Origin& from, std::uint8_t group, bool answer, std::uint8_t fallbackPrio,
                      const Payload& payload);

Message decodeSystem(const can::CanFrame& frame);
Message decodeLoco(const can::CanFrame& frame);
Message decodeDecoder(const can::CanFrame& frame);
Message decodeEncoder(const can::CanFrame& frame);
Message decodeManagement(const can::CanFrame& frame);
Message decodeFlash(const can::CanFrame& frame);

can::CanFrame encodeOne(const AllOff& m);
can::CanFrame encodeOne(const AllOn& m);
can::CanFrame encodeOne(const Overload& m);
can::CanFrame encodeOne(const LocoStop& m);
can::CanFrame encodeOne(const LocoSpeedQuery& m);
can::CanFrame encodeOne(const LocoSpeed& m);
can::CanFrame encodeOne(const LocoSpeedQueryByUid& m);
can::CanFrame encodeOne(const LocoSpeedByUid& m);
can::CanFrame encodeOne(const LocoFunctionsQuery& m);
can::CanFrame encodeOne(const LocoFunctions& m);
can::CanFrame encodeOne(const LocoFunctionQuery& m);
can::CanFrame encodeOne(const LocoFunction& m);
can::CanFrame encodeOne(const AllDecoders& m);
can::CanFrame encodeOne(const DecoderSwitch& m);
can::CanFrame encodeOne(const AllEncoders& m);
can::CanFrame encodeOne(const EncoderQuery& m);
can::CanFrame encodeOne(const EncoderStatus& m);
can::CanFrame encodeOne(const Ping& m);
can::CanFrame encodeOne(const PingAnswer& m);
can::CanFrame encodeOne(const Find& m);
can::CanFrame encodeOne(const FindAnswer& m);
can::CanFrame encodeOne(const AssignBusId& m);
can::CanFrame encodeOne(const FlashCancel& m);
can::CanFrame encodeOne(const FlashInit& m);
can::CanFrame encodeOne(const FlashAccepted& m);
can::CanFrame encodeOne(const FlashSize& m);
can::CanFrame encodeOne(const FlashSizeAnswer& m);
can::CanFrame encodeOne(const FlashData& m);
can::CanFrame encodeOne(const FlashChecksum& m);
can::CanFrame encodeOne(const Unknown& m);

} // namespace stellwerk::orc::detail
