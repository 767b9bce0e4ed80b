#include "cs2/Codec.h"

#include "cs2/CodecDetail.h"

namespace stellwerk::cs2 {
namespace detail {

std::uint8_t commandOf(const MessageBody& body) {
    return std::visit(
        [](const auto& m) -> std::uint8_t {
            using T = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<T, Unknown>)
                return m.command;
            else
                return std::uint8_t(T::command);
        },
        body);
}

} // namespace detail

namespace {

detail::BodyResult decodeBody(const CanFrame& frame) {
    const detail::Reader r(frame);
    const std::uint8_t command = cs2::command(frame);
    switch (Command(command)) {
    case Command::System:
        return detail::decodeSystem(r);
    case Command::LocoDiscovery:
    case Command::MfxBind:
    case Command::MfxVerify:
    case Command::LocoSpeed:
    case Command::LocoDirection:
    case Command::LocoFunction:
    case Command::ConfigRead:
    case Command::ConfigWrite:
        return detail::decodeManagement(command, r);
    case Command::AccessorySwitch:
    case Command::AccessoryConfig:
        return detail::decodeAccessory(command, r);
    case Command::S88Poll:
    case Command::S88Event:
    case Command::Sx1Event:
        return detail::decodeFeedback(command, r);
    case Command::Ping:
    case Command::UpdateOffer:
    case Command::ReadConfigData:
    case Command::BootloaderCan:
    case Command::BootloaderTrack:
    case Command::StatusDataConfig:
        return detail::decodeDevice(command, r);
    case Command::ConfigDataRequest:
    case Command::ConfigDataStream:
    case Command::Connect6021Stream:
        return detail::decodeStream(command, r);
    case Command::AutomationSwitch:
        return detail::decodeAutomation(r);
    }
    return MessageBody(Unknown{command, r.raw()});
}

} // namespace

DecodeResult decode(const CanFrame& frame) {
    if (frame.dlc > 8)
        return DecodeError{DecodeErrorKind::DlcOutOfRange, cs2::command(frame), frame.dlc,
                           "a CAN frame has at most 8 data bytes"};
    if (!frame.extended)
        return DecodeError{DecodeErrorKind::IdOutOfRange, cs2::command(frame), frame.dlc,
                           "a CS2 frame has a 29-bit identifier; this is a standard (11-bit) frame"};
    if (frame.id & ~CanFrame::ExtendedIdMask)
        return DecodeError{DecodeErrorKind::IdOutOfRange, cs2::command(frame), frame.dlc,
                           "a CAN identifier has 29 bits; bits 29..31 must be zero"};
    auto body = decodeBody(frame);
    if (!body)
        return body.error();
    return Message{cs2::prio(frame), cs2::isResponse(frame), cs2::hash(frame), std::move(*body)};
}

CanFrame encode(const Message& message) {
    CanFrame frame;
    frame.id = makeId(message.prio, detail::commandOf(message.body), message.response, message.hash);
    detail::Writer writer(frame);
    std::visit([&](const auto& body) { detail::encode(body, writer); }, message.body);
    return frame;
}

std::string_view messageName(const MessageBody& body) {
    return std::visit([](const auto& m) { return std::decay_t<decltype(m)>::name; }, body);
}

std::optional<std::uint8_t> systemSubcommand(const MessageBody& body) {
    if (detail::commandOf(body) != 0)
        return std::nullopt;
    const CanFrame frame = encode(Message{0, false, 0, body});
    return frame.dlc >= 5 ? std::optional(frame.data[4]) : std::nullopt;
}

std::string_view decodeErrorKindName(DecodeErrorKind kind) {
    switch (kind) {
    case DecodeErrorKind::DlcOutOfRange:
        return "dlc-out-of-range";
    case DecodeErrorKind::IdOutOfRange:
        return "id-out-of-range";
    case DecodeErrorKind::TooShort:
        return "too-short";
    case DecodeErrorKind::UnexpectedLength:
        return "unexpected-length";
    case DecodeErrorKind::ReservedValue:
        return "reserved-value";
    }
    return "invalid";
}

std::string DecodeError::message() const {
    std::string text;
    switch (kind) {
    case DecodeErrorKind::DlcOutOfRange:
        text = "DLC " + std::to_string(dlc) + " is above 8";
        break;
    case DecodeErrorKind::IdOutOfRange:
        text = "identifier out of range";
        break;
    case DecodeErrorKind::TooShort:
        text = "too short (" + std::to_string(dlc) + " data bytes)";
        break;
    case DecodeErrorKind::UnexpectedLength:
        text = "unexpected length " + std::to_string(dlc);
        break;
    case DecodeErrorKind::ReservedValue:
        text = "reserved value";
        break;
    }
    return text + ": " + std::string(detail);
}

} // namespace stellwerk::cs2
