#include "cs2config/Text.h"

#include <cstdint>

namespace stellwerk::cs2config {

namespace {

// Length of the UTF-8 sequence starting at bytes[i], or 0 when it is malformed.
std::size_t sequenceLength(std::string_view bytes, std::size_t i) {
    const auto lead = static_cast<std::uint8_t>(bytes[i]);
    std::size_t length = 0;
    std::uint32_t minimum = 0;
    std::uint32_t code = 0;
    if (lead >= 0xC2 && lead <= 0xDF) {
        length = 2, minimum = 0x80, code = lead & 0x1Fu;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
        length = 3, minimum = 0x800, code = lead & 0x0Fu;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
        length = 4, minimum = 0x10000, code = lead & 0x07u;
    } else {
        return 0;
    }
    if (i + length > bytes.size())
        return 0;
    for (std::size_t k = 1; k < length; ++k) {
        const auto next = static_cast<std::uint8_t>(bytes[i + k]);
        if ((next & 0xC0u) != 0x80u)
            return 0;
        code = (code << 6) | (next & 0x3Fu);
    }
    const bool surrogate = code >= 0xD800 && code <= 0xDFFF;
    return code < minimum || code > 0x10FFFF || surrogate ? 0 : length;
}

} // namespace

bool isValidUtf8(std::string_view bytes) {
    std::size_t i = 0;
    while (i < bytes.size()) {
        if (static_cast<std::uint8_t>(bytes[i]) < 0x80) {
            ++i;
            continue;
        }
        const std::size_t length = sequenceLength(bytes, i);
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
