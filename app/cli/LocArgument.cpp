#include "LocArgument.h"

#include "CliNumber.h"
#include "cs2/LocIdText.h"

#include <array>
#include <charconv>
#include <cstdio>
#include <limits>
#include <optional>
#include <utility>

namespace stellwerk::cli {
namespace {

std::string quoted(std::string_view text) {
    return "'" + std::string(text) + "'";
}

std::string hexText(std::uint32_t value) {
    std::array<char, 16> buffer{};
    std::snprintf(buffer.data(), buffer.size(), "0x%04X", unsigned(value));
    return buffer.data();
}

// "mfx:5" -> (mfx, "5"); the whole text as the address when there is no colon.
std::pair<std::string_view, std::string_view> splitProtocol(std::string_view text) {
    const auto colon = text.find(':');
    if (colon == std::string_view::npos)
        return {{}, text};
    return {text.substr(0, colon), text.substr(colon + 1)};
}

std::optional<cs2::Protocol> accessoryProtocol(std::string_view name) {
    if (name.empty() || name == "mm2" || name == "mm")
        return cs2::Protocol::Mm2Accessory;
    if (name == "dcc")
        return cs2::Protocol::DccAccessory;
    if (name == "sx1")
        return cs2::Protocol::Sx1Accessory;
    return std::nullopt;
}

} // namespace

Expected<cs2::LocId, std::string> parseLocomotive(std::string_view text) {
    return cs2::parseLocomotive(text);
}

Expected<cs2::LocId, std::string> parseAccessory(std::string_view text) {
    const auto [protocolName, addressText] = splitProtocol(text);
    bool hex = false;
    const auto address = parseNumber(addressText, std::numeric_limits<std::uint32_t>::max(), &hex);
    if (protocolName.empty() && hex && address && *address <= 0xFFFF)
        return cs2::LocId(*address);
    const auto protocol = accessoryProtocol(protocolName);
    if (!protocol)
        return "ADDR " + quoted(text) + ": unknown protocol " + quoted(protocolName) + " (mm2, dcc, sx1)";
    const auto id = address && !hex ? cs2::LocId::fromAddress(*protocol, *address) : std::nullopt;
    if (!id)
        return "ADDR " + quoted(text) + " is not an accessory number (1-based, as on the keyboard)";
    return *id;
}

std::string locomotiveText(cs2::LocId loco) {
    return cs2::locomotiveText(loco);
}

std::string accessoryText(cs2::LocId article) {
    switch (article.protocol()) {
    case cs2::Protocol::Mm2Accessory:
        return "mm2:" + std::to_string(article.address());
    case cs2::Protocol::DccAccessory:
        return "dcc:" + std::to_string(article.address());
    case cs2::Protocol::Sx1Accessory:
        return "sx1:" + std::to_string(article.address());
    default:
        return hexText(article.value());
    }
}

Expected<cs2::Direction, std::string> parseDirection(std::string_view text) {
    if (text == "forward" || text == "1")
        return cs2::Direction::Forward;
    if (text == "backward" || text == "2")
        return cs2::Direction::Backward;
    if (text == "toggle" || text == "3")
        return cs2::Direction::Toggle;
    return "direction " + quoted(text) + " is not forward, backward or toggle";
}

std::string_view directionText(std::uint8_t direction) {
    switch (direction) {
    case std::uint8_t(cs2::Direction::Forward):
        return "forward";
    case std::uint8_t(cs2::Direction::Backward):
        return "backward";
    case std::uint8_t(cs2::Direction::Toggle):
        return "toggle";
    default:
        return "keep";
    }
}

Expected<std::uint16_t, std::string> parseSpeed(std::string_view text) {
    const auto speed = parseNumber(text);
    if (!speed || *speed > 1000)
        return "speed " + quoted(text) + " is not a number from 0 to 1000";
    return std::uint16_t(*speed);
}

Expected<std::uint8_t, std::string> parseFunctionNumber(std::string_view text) {
    if (!text.empty() && (text[0] == 'f' || text[0] == 'F'))
        text.remove_prefix(1);
    const auto number = parseNumber(text);
    if (!number || *number > 31)
        return "function " + quoted(text) + " is not a number from 0 to 31";
    return std::uint8_t(*number);
}

Expected<bool, std::string> parseOnOff(std::string_view text) {
    if (text == "on" || text == "1")
        return true;
    if (text == "off" || text == "0")
        return false;
    return "function value " + quoted(text) + " is not on or off";
}

Expected<std::uint8_t, std::string> parsePosition(std::string_view text) {
    static constexpr std::array<std::pair<std::string_view, std::uint8_t>, 13> Names{{
        {"red", 0},
        {"round", 0},
        {"right", 0},
        {"off", 0},
        {"hp0", 0},
        {"green", 1},
        {"straight", 1},
        {"on", 1},
        {"hp1", 1},
        {"yellow", 2},
        {"left", 2},
        {"hp2", 2},
        {"white", 3},
    }};
    for (const auto& [name, value] : Names)
        if (text == name)
            return value;
    if (text == "sh0")
        return std::uint8_t(3);
    const auto number = parseNumber(text);
    if (!number || *number > 255)
        return "position " + quoted(text) + " is not 0..255, red, green, round, straight, yellow or white";
    return std::uint8_t(*number);
}

Expected<std::uint32_t, std::string> parseUid(std::string_view text) {
    const auto uid = parseNumber(text);
    if (!uid)
        return "UID " + quoted(text) + " is not a number (decimal or 0x...)";
    return *uid;
}

} // namespace stellwerk::cli
