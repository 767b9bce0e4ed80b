#include "withrottle/Text.h"

#include <charconv>

namespace stellwerk::withrottle {

std::string cleanText(std::string_view text) {
    std::string clean;
    clean.reserve(text.size());
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        clean.push_back(byte < 0x20 || byte == 0x7F ? ' ' : c);
    }
    for (const std::string_view delimiter : {EntrySeparator, PartSeparator, CommandSeparator})
        for (std::size_t at = clean.find(delimiter); at != std::string::npos; at = clean.find(delimiter, at))
            clean[at + 1] = ' ';
    return clean;
}

std::vector<std::string_view> split(std::string_view text, std::string_view separator) {
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    for (std::size_t at = text.find(separator); at != std::string_view::npos;
         at = text.find(separator, start)) {
        parts.push_back(text.substr(start, at - start));
        start = at + separator.size();
    }
    parts.push_back(text.substr(start));
    return parts;
}

std::optional<int> parseNumber(std::string_view text, int low, int high) {
    if (text.empty() || text.front() == '+')
        return std::nullopt;
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{} || end != text.data() + text.size() || value < low || value > high)
        return std::nullopt;
    return value;
}

} // namespace stellwerk::withrottle
