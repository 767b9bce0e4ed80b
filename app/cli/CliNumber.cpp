#include "CliNumber.h"

#include <charconv>
#include <cstdio>

namespace stellwerk::cli {

std::optional<std::uint32_t> parseNumber(std::string_view text, std::uint32_t max, bool* wasHex) {
    const bool hex = text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X');
    if (wasHex)
        *wasHex = hex;
    if (hex)
        text.remove_prefix(2);
    std::uint32_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value, hex ? 16 : 10);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || value > max)
        return std::nullopt;
    return value;
}

std::string hexNumber(std::uint32_t value, int digits) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%0*X", digits, unsigned(value));
    return text;
}

} // namespace stellwerk::cli
