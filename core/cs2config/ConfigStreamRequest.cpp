#include "cs2config/ConfigStreamRequest.h"

#include "cs2/Codec.h"
#include "cs2config/ConfigStreamKeys.h"

#include <charconv>

namespace stellwerk::cs2config {
namespace {

// Cuts UTF-8 text to at most `limit` bytes without splitting a multi-byte character.
std::string_view cutUtf8(std::string_view text, std::size_t limit) {
    if (text.size() <= limit)
        return text;
    std::size_t end = limit;
    while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80)
        --end;
    return text.substr(0, end);
}

can::CanFrame requestFrame(std::string_view eightBytes, std::uint16_t hash, bool response) {
    cs2::ConfigDataRequest body;
    for (std::size_t i = 0; i < eightBytes.size() && i < body.filename.size(); ++i)
        body.filename[i] = eightBytes[i];
    return cs2::encode(cs2::Message{0, response, hash, body});
}

Expected<ConfigRequest, std::string> rangeRequest(std::string_view key, unsigned first, unsigned count) {
    return ConfigRequest::forKey(key, std::to_string(first) + " " + std::to_string(count));
}

std::optional<unsigned> number(std::string_view text) {
    unsigned value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size())
        return std::nullopt;
    return value;
}

} // namespace

Expected<ConfigRequest, std::string> ConfigRequest::forKey(std::string_view key, std::string_view qualifier) {
    if (key.empty() || key.size() > MaxKeyLength)
        return "config key '" + std::string(key) + "' must have 1 to 8 bytes";
    if (key.find('\0') != std::string_view::npos || qualifier.find('\0') != std::string_view::npos)
        return "config key '" + std::string(key) + "': NUL bytes cannot be sent, they end the text";
    const auto row = findConfigFileKey(key);
    const std::size_t room = row ? 8u * row->followUpFrames() : 0u;
    if (qualifier.size() > room)
        return room == 0 ? "config key '" + std::string(key) + "' takes no follow-up frame"
                         : "config key '" + std::string(key) + "': '" + std::string(qualifier) + "' has " +
                               std::to_string(qualifier.size()) + " bytes, the follow-up frames hold " +
                               std::to_string(room);
    return ConfigRequest(std::string(key), std::string(qualifier));
}

ConfigRequest ConfigRequest::locoInfo(std::string_view locoName) {
    return ConfigRequest("lokinfo", std::string(cutUtf8(locoName, MaxLocoNameLength)));
}

Expected<ConfigRequest, std::string> ConfigRequest::locoNames(unsigned first, unsigned count) {
    return rangeRequest("loknamen", first, count);
}

Expected<ConfigRequest, std::string> ConfigRequest::accessoryInfo(unsigned first, unsigned count) {
    return rangeRequest("maginfo", first, count);
}

std::uint8_t ConfigRequest::followUpFrames() const {
    const auto row = findConfigFileKey(key_);
    return row ? row->followUpFrames() : 0;
}

std::optional<RequestRange> ConfigRequest::range() const {
    const auto space = qualifier_.find(' ');
    if (space == std::string::npos)
        return std::nullopt;
    const auto first = number(std::string_view(qualifier_).substr(0, space));
    const auto count = number(std::string_view(qualifier_).substr(space + 1));
    if (!first || !count)
        return std::nullopt;
    return RequestRange{*first, *count};
}

std::vector<can::CanFrame> ConfigRequest::frames(std::uint16_t hash, bool response) const {
    std::vector<can::CanFrame> out{requestFrame(key_, hash, response)};
    for (std::size_t i = 0; i < followUpFrames(); ++i) {
        const std::string_view part =
            i * 8 < qualifier_.size() ? std::string_view(qualifier_).substr(i * 8, 8) : std::string_view();
        out.push_back(requestFrame(part, hash, response));
    }
    return out;
}

} // namespace stellwerk::cs2config
