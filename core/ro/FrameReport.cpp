#include "ro/FrameReport.h"

#include "can/FrameText.h"

namespace stellwerk::ro {
namespace {

void appendValue(std::string& out, const Field& field) {
    if (field.format == Field::Format::Text) {
        out += field.text;
        return;
    }
    out += "0x";
    can::appendHex(out, field.number, field.digits);
}

std::string_view directionName(Direction direction) {
    return direction == Direction::Request ? "request" : "answer";
}

Field hexField(std::string_view key, std::uint32_t number, unsigned digits = 2) {
    return Field{key, number, Field::Format::Hex, digits, {}};
}

Field widthField(Width width) {
    return Field{"width", std::uint32_t(width), Field::Format::Text, 0, widthName(width)};
}

unsigned valueDigits(Width width) {
    return width == Width::None ? 8 : 2 * std::max(1u, byteCount(width));
}

std::variant<Request, Answer, DecodeError> decodeAs(const can::CanFrame& frame, Direction direction) {
    if (direction == Direction::Request) {
        auto request = decodeRequest(frame.payload());
        return request ? std::variant<Request, Answer, DecodeError>(*request) : request.error();
    }
    auto answer = decodeAnswer(frame.payload());
    return answer ? std::variant<Request, Answer, DecodeError>(*answer) : answer.error();
}

} // namespace

std::vector<Field> describe(const Request& request) {
    std::vector<Field> fields{widthField(request.width), hexField("address", request.address, 4),
                              hexField("job", request.job)};
    if (request.isWrite())
        fields.push_back(hexField("value", request.value, valueDigits(request.width)));
    return fields;
}

std::vector<Field> describe(const Answer& answer) {
    if (const auto* ok = std::get_if<OkAnswer>(&answer))
        return {widthField(ok->width), hexField("job", ok->job),
                hexField("value", ok->value, valueDigits(ok->width))};
    if (const auto* duplicate = std::get_if<DuplicateJobAnswer>(&answer)) {
        std::vector<Field> fields{hexField("job", duplicate->job)};
        if (duplicate->dataBytes > 0)
            fields.push_back(hexField("value", duplicate->value, 2u * duplicate->dataBytes));
        return fields;
    }
    return {};
}

FrameReport::FrameReport(const can::CanFrame& frame, Direction direction)
    : frame_(frame), direction_(direction), message_(decodeAs(frame, direction)) {
    if (const auto* request = std::get_if<Request>(&message_))
        fields_ = describe(*request);
    else if (const auto* answer = std::get_if<Answer>(&message_))
        fields_ = describe(*answer);
}

std::string_view FrameReport::name() const {
    if (const auto* request = std::get_if<Request>(&message_))
        return request->name();
    if (const auto* answer = std::get_if<Answer>(&message_))
        return nameOf(*answer);
    return "ro.unknown";
}

std::string FrameReport::detailText() const {
    std::string text = "direction=";
    text += directionName(direction_);
    if (const auto* error = std::get_if<DecodeError>(&message_)) {
        text += " error=\"";
        text += error->reason;
        if (error->byte)
            text += " (byte " + std::to_string(error->byte) + ")";
        return text + "\"";
    }
    for (const Field& field : fields_) {
        text += ' ';
        text += field.key;
        text += '=';
        appendValue(text, field);
    }
    return text;
}

std::string FrameReport::text() const {
    std::string text = can::formatDocument(frame_);
    text += "  ";
    text += name();
    text += "  ";
    return text + detailText();
}

std::string FrameReport::json() const {
    std::string json = "{\"id\":\"";
    json.reserve(192);
    json += can::formatId(frame_);
    json += frame_.extended ? "\",\"extended\":true" : "\",\"extended\":false";
    json += ",\"dlc\":" + std::to_string(frame_.dlc) + ",\"data\":\"";
    for (const std::uint8_t byte : frame_.payload())
        can::appendHex(json, byte, 2);
    json += "\",\"name\":\"";
    json += name();
    json += "\",\"direction\":\"";
    json += directionName(direction_);
    json += '"';
    if (const auto* error = std::get_if<DecodeError>(&message_))
        return json + ",\"error\":\"" + error->reason + "\",\"byte\":" + std::to_string(error->byte) + "}";
    json += ",\"fields\":{";
    for (std::size_t i = 0; i < fields_.size(); ++i) {
        json += i ? ",\"" : "\"";
        json += fields_[i].key;
        json += "\":\"";
        appendValue(json, fields_[i]);
        json += '"';
    }
    return json + "}}";
}

std::optional<std::uint64_t> FrameReport::number(std::string_view key) const {
    for (const Field& field : fields_)
        if (field.key == key)
            return field.number;
    return std::nullopt;
}

std::vector<std::string_view> messageNames() {
    std::vector<std::string_view> names;
    for (const auto kind : {Request::Kind::Write, Request::Kind::Read})
        for (const auto width : {Width::Bit, Width::Byte, Width::Word, Width::Long})
            names.push_back(Request{kind, width}.name());
    names.insert(names.end(),
                 {OkAnswer::name, DuplicateJobAnswer::name, InvalidCommandAnswer::name, "ro.unknown"});
    return names;
}

} // namespace stellwerk::ro
