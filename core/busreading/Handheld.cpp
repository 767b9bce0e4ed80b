#include "busreading/Handheld.h"

#include <algorithm>
#include <cctype>
#include <charconv>

namespace stellwerk::busreading {
namespace {

// Nodes 0..125 pair up as master/slave (0/1, 42/43, ...); 126 and 127 are the login and flash nodes.
constexpr unsigned LastPairNode = 125;

std::string lowerTrimmed(std::string_view text) {
    const auto blank = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
    while (!text.empty() && blank(text.front()))
        text.remove_prefix(1);
    while (!text.empty() && blank(text.back()))
        text.remove_suffix(1);
    std::string lower(text);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](char c) { return char(std::tolower(static_cast<unsigned char>(c))); });
    return lower;
}

bool allDigits(std::string_view text) {
    return !text.empty() && std::all_of(text.begin(), text.end(),
                                        [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

} // namespace

std::optional<HandheldReference> HandheldReference::parse(std::string_view text) {
    HandheldReference reference;
    reference.name_ = lowerTrimmed(text);
    if (reference.name_.empty())
        return std::nullopt;
    if (!allDigits(reference.name_))
        return reference;
    unsigned node = 0;
    const std::string& digits = reference.name_;
    if (std::from_chars(digits.data(), digits.data() + digits.size(), node).ec != std::errc() ||
        node > LastPairNode)
        return std::nullopt;
    reference.node_ = std::uint8_t(node | 1);
    return reference;
}

bool HandheldReference::matches(const Handheld& handheld) const {
    if (node_)
        return handheld.node == *node_;
    return lowerTrimmed(handheld.name) == name_;
}

} // namespace stellwerk::busreading
