#include "can/ReportFields.h"

#include "can/FrameText.h"

namespace stellwerk::can {
namespace {

// The reports are built by appending to one string: the bus monitor and the fuzz targets make one per
// frame, and temporaries per field cost more than the text itself.
void appendQuoted(std::string& out, std::string_view text) {
    out += '"';
    for (const char c : text) {
        if (c == '"' || c == '\\')
            out += '\\';
        out += c;
    }
    out += '"';
}

bool isBareText(std::string_view text) {
    return !text.empty() && text.find(' ') == std::string_view::npos;
}

void appendValue(std::string& out, const Field& field, bool json) {
    switch (field.format) {
    case FieldFormat::Hex:
        out += json ? "\"0x" : "0x";
        appendHex(out, field.number, field.digits);
        if (json)
            out += '"';
        return;
    case FieldFormat::Bool:
        out += field.number ? "true" : "false";
        return;
    case FieldFormat::Text:
        if (!json && isBareText(field.text))
            out += field.text;
        else
            appendQuoted(out, field.text);
        return;
    case FieldFormat::Decimal:
        break;
    }
    out += std::to_string(field.number);
}

void appendFields(std::string& out, const std::vector<Field>& fields) {
    for (std::size_t i = 0; i < fields.size(); ++i) {
        if (i > 0)
            out += ' ';
        out += fields[i].key;
        out += '=';
        appendValue(out, fields[i], false);
    }
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
    std::string out;
    appendHex(out, value, digits);
    return out;
}

std::string fieldsText(const std::vector<Field>& fields) {
    std::string text;
    text.reserve(24 * fields.size());
    appendFields(text, fields);
    return text;
}

std::string reportText(const CanFrame& frame, std::string_view name, const std::vector<Field>& fields) {
    std::string text = formatDocument(frame);
    text += "  ";
    text += name;
    text += "  ";
    appendFields(text, fields);
    return text;
}

std::string reportJson(const CanFrame& frame, std::string_view name, const std::vector<Field>& fields) {
    std::string json;
    json.reserve(96 + name.size() + 32 * fields.size());
    json += "{\"id\":\"";
    json += formatId(frame);
    json += "\",\"dlc\":";
    json += std::to_string(frame.dlc);
    json += ",\"data\":\"";
    for (const std::uint8_t byte : frame.payload())
        appendHex(json, byte, 2);
    json += "\",\"name\":\"";
    json += name;
    json += "\",\"fields\":{";
    for (std::size_t i = 0; i < fields.size(); ++i) {
        if (i > 0)
            json += ',';
        appendQuoted(json, fields[i].key);
        json += ':';
        appendValue(json, fields[i], true);
    }
    json += "}}";
    return json;
}

std::optional<std::uint64_t> fieldNumber(const std::vector<Field>& fields, std::string_view key) {
    for (const Field& field : fields)
        if (field.key == key && field.format != FieldFormat::Text)
            return field.number;
    return std::nullopt;
}

} // namespace stellwerk::can
