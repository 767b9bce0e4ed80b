#include "cs2/LocIdText.h"

#include <array>
#include <charconv>
#include <cstdio>
#include <optional>
#include <utility>

namespace stellwerk::cs2 {
namespace {

std::string quoted(std::string_view text) {
    return "'" + std::string(text) + "'";
}

// A whole decimal number, or hex with 0x; nullopt for anything else.
std::optional<std::uint32_t> wholeNumber(std::string_view text) {
    const bool hex = text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X');
    if (hex)
        text.remove_prefix(2);
    std::uint32_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value, hex ? 16 : 10);
    if (text.empty() || error != std::errc() || end != text.data() + text.size())
        return std::nullopt;
    return value;
}

// "mfx:5" -> (mfx, "5"); the whole text as the address when there is no colon.
std::pair<std::string_view, std::string_view> splitProtocol(std::string_view text) {
    const auto colon = text.find(':');
    if (colon == std::string_view::npos)
        return {{}, text};
    return {text.substr(0, colon), text.substr(colon + 1)};
}

bool isLocoProtocol(std::optional<Protocol> protocol) {
    return protocol &&
           (*protocol == Protocol::Mm2 || *protocol == Protocol::Mfx || *protocol == Protocol::Dcc ||
            *protocol == Protocol::Sx1 || *protocol == Protocol::Sx2);
}

} // namespace

Expected<LocId, std::string> parseLocomotive(std::string_view text) {
    const auto [protocolName, addressText] = splitProtocol(text);
    const auto address = wholeNumber(addressText);
    if (protocolName.empty()) {
        if (!address || *address > 0xFFFF)
            return "LOC " + quoted(text) + " is not mfx:N, dcc:N, mm2:N or a Loc-ID up to 0xFFFF";
        return LocId(*address);
    }
    const auto protocol = protocolFromName(protocolName);
    if (!isLocoProtocol(protocol))
        return "LOC " + quoted(text) + ": unknown protocol " + quoted(protocolName) +
               " (mfx, dcc, mm2, sx1, sx2)";
    const auto id = address ? LocId::fromAddress(*protocol, *address) : std::nullopt;
    if (!id)
        return "LOC " + quoted(text) + ": the address does not fit the " + std::string(protocolName) +
               " range";
    return *id;
}

std::string locomotiveText(LocId loco) {
    switch (loco.protocol()) {
    case Protocol::Mm2:
    case Protocol::Mfx:
    case Protocol::Dcc:
    case Protocol::Sx1:
    case Protocol::Sx2:
        return std::string(protocolName(loco.protocol())) + ":" + std::to_string(loco.address());
    default:
        break;
    }
    std::array<char, 16> buffer{};
    std::snprintf(buffer.data(), buffer.size(), "0x%04X", unsigned(loco.value()));
    return buffer.data();
}

} // namespace stellwerk::cs2
