#include "cs2config/Text.h"

#include "cs2/JsonText.h"

#include <cstdint>

namespace stellwerk::cs2config {

bool isValidUtf8(std::string_view bytes) {
    std::size_t i = 0;
    while (i < bytes.size()) {
        if (static_cast<std::uint8_t>(bytes[i]) < 0x80) { // most text: no call per character
            ++i;
            continue;
        }
        const std::size_t length = cs2::utf8SequenceLength(bytes, i);
        if (length == 0)
            return false;
        i += length;
    }
    return true;
}

std::string latin1ToUtf8(std::string_view bytes) {
    std::string text;
    text.reserve(bytes.size() + bytes.size() / 4);
    for (char c : bytes) {
        const auto byte = static_cast<std::uint8_t>(c);
        if (byte < 0x80) {
            text += c;
        } else {
            text += static_cast<char>(0xC0 | (byte >> 6));
            text += static_cast<char>(0x80 | (byte & 0x3F));
        }
    }
    return text;
}

std::string quoteForMessage(std::string_view line, std::size_t limit) {
    static constexpr char hex[] = "0123456789ABCDEF";
    std::string text = "'";
    std::size_t i = 0;
    for (; i < line.size(); ++i) {
        const auto byte = static_cast<std::uint8_t>(line[i]);
        const bool continuation = (byte & 0xC0u) == 0x80u;
        if (i >= limit && !continuation)
            break;
        if (byte < 0x20 || byte == 0x7F) {
            text += "\\x";
            text += hex[byte >> 4];
            text += hex[byte & 0x0F];
        } else {
            text += line[i];
        }
    }
    if (i < line.size())
        text += "...";
    return text + "'";
}

} // namespace stellwerk::cs2config
