#pragma once

// Internal to the codec: byte access for decoders and encoders, and the per-message functions.

#include "base/Expected.h"
#include "cs2/DecodeError.h"
#include "cs2/Header.h"
#include "cs2/Messages.h"

#include <string_view>

namespace stellwerk::cs2::detail {

using BodyResult = Expected<MessageBody, DecodeError>;

inline std::uint16_t be16(const RawBytes& raw, std::size_t i) {
    return std::uint16_t((raw.bytes[i] << 8) | raw.bytes[i + 1]);
}
inline std::uint32_t be32(const RawBytes& raw, std::size_t i) {
    return (std::uint32_t(be16(raw, i)) << 16) | be16(raw, i + 2);
}

// Big-endian reads from a frame whose DLC is known to be at most 8.
class Reader {
public:
    explicit Reader(const CanFrame& frame) : frame_(frame) {}

    std::size_t size() const { return frame_.dlc; }
    bool response() const { return cs2::isResponse(frame_); }
    std::uint8_t u8(std::size_t i) const { return frame_.data[i]; }
    std::uint16_t u16(std::size_t i) const {
        return std::uint16_t((frame_.data[i] << 8) | frame_.data[i + 1]);
    }
    std::uint32_t u32(std::size_t i) const {
        return (std::uint32_t(frame_.data[i]) << 24) | (std::uint32_t(frame_.data[i + 1]) << 16) |
               (std::uint32_t(frame_.data[i + 2]) << 8) | frame_.data[i + 3];
    }
    RawBytes raw() const {
        RawBytes out;
        out.size = frame_.dlc;
        out.bytes = frame_.data;
        for (std::size_t i = out.size; i < 8; ++i)
            out.bytes[i] = 0;
        return out;
    }

    DecodeError tooShort(std::string_view detail) const { return error(DecodeErrorKind::TooShort, detail); }
    DecodeError length(std::string_view detail) const {
        return error(DecodeErrorKind::UnexpectedLength, detail);
    }
    DecodeError reserved(std::string_view detail) const {
        return error(DecodeErrorKind::ReservedValue, detail);
    }

private:
    DecodeError error(DecodeErrorKind kind, std::string_view detail) const {
        return {kind, cs2::command(frame_), frame_.dlc, detail};
    }
    const CanFrame& frame_;
};

// Appends big-endian values to a frame's data and keeps its DLC.
class Writer {
public:
    explicit Writer(CanFrame& frame) : frame_(frame) {
        frame_.dlc = 0;
        frame_.data.fill(0);
    }
    Writer& u8(std::uint8_t v) {
        frame_.data[frame_.dlc++] = v;
        return *this;
    }
    Writer& u16(std::uint16_t v) { return u8(std::uint8_t(v >> 8)).u8(std::uint8_t(v)); }
    Writer& u32(std::uint32_t v) { return u16(std::uint16_t(v >> 16)).u16(std::uint16_t(v)); }
    Writer& raw(const RawBytes& raw) {
        for (std::size_t i = 0; i < raw.size && i < 8; ++i)
            u8(raw.bytes[i]);
        return *this;
    }

private:
    CanFrame& frame_;
};

// Decoders for each command group; the Reader's DLC is already checked to be at most 8.
BodyResult decodeSystem(const Reader& r);
BodyResult decodeManagement(std::uint8_t command, const Reader& r);
BodyResult decodeAccessory(std::uint8_t command, const Reader& r);
BodyResult decodeFeedback(std::uint8_t command, const Reader& r);
BodyResult decodeDevice(std::uint8_t command, const Reader& r);
BodyResult decodeStream(std::uint8_t command, const Reader& r);
BodyResult decodeAutomation(const Reader& r);

// The command number each body type is sent with.
std::uint8_t commandOf(const MessageBody& body);

void encode(const Unknown& m, Writer& w);
void encode(const SystemStop& m, Writer& w);
void encode(const SystemGo& m, Writer& w);
void encode(const SystemHalt& m, Writer& w);
void encode(const LocoEmergencyStop& m, Writer& w);
void encode(const LocoCycleEnd& m, Writer& w);
void encode(const LocoProtocol& m, Writer& w);
void encode(const AccessorySwitchTime& m, Writer& w);
void encode(const MfxFastRead& m, Writer& w);
void encode(const TrackProtocols& m, Writer& w);
void encode(const MfxRegistrationCounter& m, Writer& w);
void encode(const Overload& m, Writer& w);
void encode(const SystemStatus& m, Writer& w);
void encode(const DeviceId& m, Writer& w);
void encode(const SystemReset& m, Writer& w);
void encode(const MfxSeek& m, Writer& w);
void encode(const LocoDiscovery& m, Writer& w);
void encode(const MfxBind& m, Writer& w);
void encode(const MfxVerify& m, Writer& w);
void encode(const LocoSpeed& m, Writer& w);
void encode(const LocoDirection& m, Writer& w);
void encode(const LocoFunction& m, Writer& w);
void encode(const ConfigRead& m, Writer& w);
void encode(const ConfigWrite& m, Writer& w);
void encode(const AccessorySwitch& m, Writer& w);
void encode(const AccessoryConfig& m, Writer& w);
void encode(const S88Poll& m, Writer& w);
void encode(const S88Event& m, Writer& w);
void encode(const Sx1Event& m, Writer& w);
void encode(const Ping& m, Writer& w);
void encode(const UpdateOffer& m, Writer& w);
void encode(const ReadConfigData& m, Writer& w);
void encode(const BootloaderCan& m, Writer& w);
void encode(const BootloaderTrack& m, Writer& w);
void encode(const StatusDataConfig& m, Writer& w);
void encode(const ConfigDataRequest& m, Writer& w);
void encode(const ConfigDataStream& m, Writer& w);
void encode(const Connect6021Stream& m, Writer& w);
void encode(const AutomationSwitch& m, Writer& w);

} // namespace stellwerk::cs2::detail
