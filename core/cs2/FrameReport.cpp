#include "cs2/FrameReport.h"

#include "can/FrameText.h"
#include "cs2/Fields.h"
#include "cs2/JsonText.h"

#include <cstdio>

namespace stellwerk::cs2 {
namespace {

std::string hex(std::uint64_t value, unsigned digits) {
    char buffer[24];
    std::snprintf(buffer, sizeof buffer, "%0*llX", int(digits), static_cast<unsigned long long>(value));
    return buffer;
}

std::string textValue(const Field& field) {
    switch (field.format) {
    case FieldFormat::Hex:
        return "0x" + hex(field.number, field.digits);
    case FieldFormat::Bool:
        return field.number ? "true" : "false";
    case FieldFormat::Text:
        return field.text.find(' ') == std::string::npos && !field.text.empty() ? field.text
                                                                                : "\"" + field.text + "\"";
    case FieldFormat::Decimal:
        break;
    }
    return std::to_string(field.number);
}

std::string jsonValue(const Field& field) {
    switch (field.format) {
    case FieldFormat::Hex:
        return "\"0x" + hex(field.number, field.digits) + "\"";
    case FieldFormat::Bool:
        return field.number ? "true" : "false";
    case FieldFormat::Text:
        return jsonQuoted(field.text);
    case FieldFormat::Decimal:
        break;
    }
    return std::to_string(field.number);
}

std::string_view systemName(std::uint8_t sub) {
    switch (sub) {
    case 0x00:
        return SystemStop::name;
    case 0x01:
        return SystemGo::name;
    case 0x02:
        return SystemHalt::name;
    case 0x03:
        return LocoEmergencyStop::name;
    case 0x04:
        return LocoCycleEnd::name;
    case 0x05:
        return LocoProtocol::name;
    case 0x06:
        return AccessorySwitchTime::name;
    case 0x07:
        return MfxFastRead::name;
    case 0x08:
        return TrackProtocols::name;
    case 0x09:
        return MfxRegistrationCounter::name;
    case 0x0A:
        return Overload::name;
    case 0x0B:
        return SystemStatus::name;
    case 0x0C:
        return DeviceId::name;
    case 0x30:
        return MfxSeek::name;
    case 0x80:
        return SystemReset::name;
    default:
        return "unknown";
    }
}

} // namespace

std::string_view intendedName(const CanFrame& frame) {
    switch (Command(cs2::command(frame))) {
    case Command::System:
        return frame.dlc >= 5 && frame.dlc <= 8 ? systemName(frame.data[4]) : "unknown";
    case Command::LocoDiscovery:
        return LocoDiscovery::name;
    case Command::MfxBind:
        return MfxBind::name;
    case Command::MfxVerify:
        return MfxVerify::name;
    case Command::LocoSpeed:
        return LocoSpeed::name;
    case Command::LocoDirection:
        return LocoDirection::name;
    case Command::LocoFunction:
        return LocoFunction::name;
    case Command::ConfigRead:
        return ConfigRead::name;
    case Command::ConfigWrite:
        return ConfigWrite::name;
    case Command::AccessorySwitch:
        return AccessorySwitch::name;
    case Command::AccessoryConfig:
        return AccessoryConfig::name;
    case Command::S88Poll:
        return S88Poll::name;
    case Command::S88Event:
        return S88Event::name;
    case Command::Sx1Event:
        return Sx1Event::name;
    case Command::Ping:
        return Ping::name;
    case Command::UpdateOffer:
        return UpdateOffer::name;
    case Command::ReadConfigData:
        return ReadConfigData::name;
    case Command::BootloaderCan:
        return BootloaderCan::name;
    case Command::BootloaderTrack:
        return BootloaderTrack::name;
    case Command::StatusDataConfig:
        return StatusDataConfig::name;
    case Command::ConfigDataRequest:
        return ConfigDataRequest::name;
    case Command::ConfigDataStream:
        return ConfigDataStream::name;
    case Command::Connect6021Stream:
        return Connect6021Stream::name;
    case Command::AutomationSwitch:
        return AutomationSwitch::name;
    }
    return "unknown";
}

FrameReport::FrameReport(const CanFrame& frame) : frame_(frame), result_(decode(frame)) {}

std::string_view FrameReport::name() const {
    return result_ ? messageName(result_->body) : intendedName(frame_);
}

std::string FrameReport::frameText() const {
    return formatDocument(frame_);
}

std::string FrameReport::detailText() const {
    if (!result_)
        return result_.error().message();
    std::string details;
    for (const auto& field : describe(*result_))
        details += (details.empty() ? "" : " ") + std::string(field.key) + "=" + textValue(field);
    return details;
}

std::string FrameReport::text() const {
    std::string line = frameText() + "  " + std::string(name());
    if (cs2::isResponse(frame_))
        line += " (response)";
    if (!result_)
        return line + "  ERROR " + detailText();
    const std::string details = detailText();
    return details.empty() ? line : line + " " + details;
}

std::string FrameReport::json() const {
    std::string out = "{\"id\":\"" + hex(frame_.id, 8) + "\"";
    out += ",\"prio\":" + std::to_string(cs2::prio(frame_));
    out += ",\"command\":" + std::to_string(cs2::command(frame_));
    out += std::string(",\"response\":") + (cs2::isResponse(frame_) ? "true" : "false");
    out += ",\"hash\":\"" + hex(cs2::hash(frame_), 4) + "\"";
    out += ",\"dlc\":" + std::to_string(frame_.dlc);
    std::string data;
    for (auto byte : frame_.payload())
        data += hex(byte, 2);
    out += ",\"data\":\"" + data + "\"";
    out += ",\"name\":" + jsonQuoted(name());
    out += ",\"fields\":{";
    if (!result_) {
        out += "\"error\":" + jsonQuoted(result_.error().message());
        out += ",\"errorKind\":" + jsonQuoted(decodeErrorKindName(result_.error().kind));
    } else {
        bool first = true;
        for (const auto& field : describe(*result_)) {
            out += (first ? "" : ",") + jsonQuoted(field.key) + ":" + jsonValue(field);
            first = false;
        }
    }
    return out + "}}";
}

} // namespace stellwerk::cs2
