#include "cs2config/JsonWriter.h"

#include "cs2/JsonText.h"

namespace stellwerk::cs2config {

std::string JsonWriter::quoted(std::string_view text) {
    return cs2::jsonQuoted(text);
}

void JsonWriter::newline() {
    if (!indented_)
        return;
    out_ += '\n';
    out_.append(first_.size() * 2, ' ');
}

void JsonWriter::prefix(std::string_view key) {
    if (!first_.empty()) {
        if (!first_.back())
            out_ += ',';
        first_.back() = false;
        newline();
    }
    if (!key.empty()) {
        out_ += quoted(key);
        out_ += indented_ ? ": " : ":";
    }
}

JsonWriter& JsonWriter::beginObject(std::string_view key) {
    prefix(key);
    out_ += '{';
    first_.push_back(true);
    return *this;
}

JsonWriter& JsonWriter::endObject() {
    const bool empty = first_.back();
    first_.pop_back();
    if (!empty)
        newline();
    out_ += '}';
    if (first_.empty() && indented_)
        out_ += '\n';
    return *this;
}

JsonWriter& JsonWriter::beginArray(std::string_view key) {
    prefix(key);
    out_ += '[';
    first_.push_back(true);
    return *this;
}

JsonWriter& JsonWriter::endArray() {
    const bool empty = first_.back();
    first_.pop_back();
    if (!empty)
        newline();
    out_ += ']';
    if (first_.empty() && indented_)
        out_ += '\n';
    return *this;
}

JsonWriter& JsonWriter::value(std::string_view key, std::string_view text) {
    prefix(key);
    out_ += quoted(text);
    return *this;
}

JsonWriter& JsonWriter::value(std::string_view key, std::int64_t number) {
    prefix(key);
    out_ += std::to_string(number);
    return *this;
}

JsonWriter& JsonWriter::value(std::string_view key, bool flag) {
    prefix(key);
    out_ += flag ? "true" : "false";
    return *this;
}

JsonWriter& JsonWriter::null(std::string_view key) {
    prefix(key);
    out_ += "null";
    return *this;
}

} // namespace stellwerk::cs2config
