#include "can/ReportFields.h"

#include "can/FrameText.h"

#include <cstdio>

namespace stellwerk::can {
namespace {

std::string quoted(std::string_view text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\')
            out += '\\';
        out += c;
    }
    return out + "\"";
}

std::string textValue(const Field& field) {
    switch (field.format) {
    case FieldFormat::Hex:
        return "0x" + hexDigits(field.number, field.digits);
    case FieldFormat::Bool:
        return field.number ? "true" : "false";
    case FieldFormat::Text:
        return field.text.find(' ') == std::string::npos && !field.text.empty() ? field.text
                                                                                : quoted(field.text);
    case FieldFormat::Decimal:
        break;
    }
    return std::to_string(field.number);
}

std::string jsonValue(const Field& field) {
    switch (field.format) {
    case FieldFormat::Hex:
        return "\"0x" + hexDigits(field.number, field.digits) + "\"";
    case FieldFormat::Bool:
        return field.number ? "true" : "false";
    case FieldFormat::Text:
        return quoted(field.text);
    case FieldFormat::Decimal:
        break;
    }
    return std::to_string(field.number);
}

} // namespace

FieldList& FieldList::number(std::string_view key, std::uint64_t value) {
    list.push_back({key, value, FieldFormat::Decimal, {}, 2});
    return *this;
}

FieldList& FieldList::hex(std::string_view key, std::uint64_t value, unsigned digits) {
    list.push_back({key, value, FieldFormat::Hex, {}, digits});
    return *this;
}

FieldList& FieldList::flag(std::string_view key, bool value) {
    list.push_back({key, value ? 1u : 0u, FieldFormat::Bool, {}, 2});
    return *this;
}

FieldList& FieldList::text(std::string_view key, std::string_view value) {
    list.push_back({key, 0, FieldFormat::Text, std::string(value), 2});
    return *this;
}

std::string hexDigits(std::uint64_t value, unsigned digits) {
    char buffer[24];
    std::snprintf(buffer, sizeof buffer, "%0*llX", int(digits), static_cast<unsigned long long>(value));
    return buffer;
}

std::string fieldsText(const std::vector<Field>& fields) {
    std::string text;
    for (const Field& field : fields)
        text += (text.empty() ? "" : " ") + std::string(field.key) + "=" + textValue(field);
    return text;
}

std::string reportJson(const CanFrame& frame, std::string_view name, const std::vector<Field>& fields) {
    const std::string candump = formatCandump(frame);
    const std::size_t hash = candump.find('#');
    std::string json = "{\"id\":\"" + candump.substr(0, hash) + "\",\"dlc\":" + std::to_string(frame.dlc) +
                       ",\"data\":\"" + candump.substr(hash + 1) + "\",\"name\":\"" + std::string(name) +
                       "\",\"fields\":{";
    for (std::size_t i = 0; i < fields.size(); ++i)
        json += (i ? "," : "") + quoted(fields[i].key) + ":" + jsonValue(fields[i]);
    return json + "}}";
}

std::optional<std::uint64_t> fieldNumber(const std::vector<Field>& fields, std::string_view key) {
    for (const Field& field : fields)
        if (field.key == key && field.format != FieldFormat::Text)
            return field.number;
    return std::nullopt;
}

} // namespace stellwerk::can
