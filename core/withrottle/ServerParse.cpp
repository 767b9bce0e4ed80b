#include "withrottle/ServerLines.h"
#include "withrottle/Text.h"

#include <array>

namespace stellwerk::withrottle {

namespace {

using Parsed = std::optional<ServerLine>;
using Parts = std::vector<std::string_view>;

std::optional<TurnoutState> turnoutState(std::string_view text) {
    if (text == "1" || text == "2" || text == "4")
        return TurnoutState(text[0] - '0');
    return std::nullopt;
}

std::optional<RouteState> routeState(std::string_view text) {
    if (text == "1" || text == "2" || text == "4")
        return RouteState(text[0] - '0');
    return std::nullopt;
}

// The entries after a list's prefix, each cut into its parts; nullopt when an entry has not `count` parts.
std::optional<std::vector<Parts>> entries(std::string_view line, std::size_t count) {
    std::vector<Parts> result;
    const Parts list = split(line, EntrySeparator);
    for (std::size_t i = 1; i < list.size(); ++i) {
        result.push_back(split(list[i], PartSeparator));
        if (result.back().size() != count)
            return std::nullopt;
    }
    return result;
}

Parsed parseRoster(std::string_view line) {
    const Parts list = split(line, EntrySeparator);
    const auto count = parseNumber(list[0].substr(2), 0, 1 << 20);
    const auto parts = entries(line, 3);
    if (!count || !parts || std::size_t(*count) != parts->size())
        return std::nullopt;
    RosterList roster;
    for (const Parts& p : *parts) {
        const auto number = parseNumber(p[1], 0, 10239);
        if (!number || (p[2] != "L" && p[2] != "S"))
            return std::nullopt;
        roster.entries.push_back({std::string(p[0]), {std::uint16_t(*number), p[2] == "L"}});
    }
    return roster;
}

// PTT/PRT]\[title}|{singular]\[on}|{2]\[off}|{4
std::optional<std::array<std::string, 4>> titles(std::string_view line) {
    const Parts list = split(line, EntrySeparator);
    if (list.size() != 4 || list[0].size() != 3)
        return std::nullopt;
    const Parts head = split(list[1], PartSeparator), on = split(list[2], PartSeparator),
                off = split(list[3], PartSeparator);
    if (head.size() != 2 || on.size() != 2 || off.size() != 2 || on[1] != "2" || off[1] != "4")
        return std::nullopt;
    return std::array<std::string, 4>{std::string(head[0]), std::string(head[1]), std::string(on[0]),
                                      std::string(off[0])};
}

Parsed parseTurnouts(std::string_view line) {
    const auto parts = entries(line, 3);
    if (!parts || line.size() < 3 || (line.size() > 3 && !line.substr(3).starts_with(EntrySeparator)))
        return std::nullopt;
    TurnoutList list;
    for (const Parts& p : *parts) {
        const auto state = turnoutState(p[2]);
        if (!state)
            return std::nullopt;
        list.turnouts.push_back({std::string(p[0]), std::string(p[1]), *state});
    }
    return list;
}

Parsed parseRoutes(std::string_view line) {
    const auto parts = entries(line, 3);
    if (!parts || (line.size() > 3 && !line.substr(3).starts_with(EntrySeparator)))
        return std::nullopt;
    RouteList list;
    for (const Parts& p : *parts) {
        const auto state = routeState(p[2]);
        if (!state && !p[2].empty())
            return std::nullopt;
        list.routes.push_back({std::string(p[0]), std::string(p[1]), state});
    }
    return list;
}

Parsed parsePanel(std::string_view line) {
    const std::string_view code = line.substr(0, 3);
    if (code == "PPA" && line.size() == 4 && line[3] >= '0' && line[3] <= '2')
        return PowerStatus{PowerState(line[3])};
    if ((code == "PTT" || code == "PRT") && titles(line)) {
        const auto t = *titles(line);
        if (code == "PTT")
            return TurnoutTitles{t[0], t[1], t[2], t[3]};
        return RouteTitles{t[0], t[1], t[2], t[3]};
    }
    if (code == "PTL")
        return parseTurnouts(line);
    if (code == "PRL")
        return parseRoutes(line);
    const auto turnout = turnoutState(line.substr(3, 1));
    if (code == "PTA" && turnout && line.size() > 4)
        return TurnoutChanged{std::string(line.substr(4)), *turnout};
    const auto route = routeState(line.substr(3, 1));
    if (code == "PRA" && route && line.size() > 4)
        return RouteChanged{std::string(line.substr(4)), *route};
    if (line.starts_with("PW"))
        if (const auto port = parseNumber(line.substr(2), 0, 65535))
            return WebPort{std::uint16_t(*port)};
    return std::nullopt;
}

std::optional<LocoUpdate> parseUpdate(std::string_view text) {
    if (text.size() < 2)
        return std::nullopt;
    const std::string_view rest = text.substr(1);
    if (text[0] == 'F' && (rest[0] == '0' || rest[0] == '1'))
        if (const auto function = parseNumber(rest.substr(1), 0, 255))
            return FunctionState{std::uint8_t(*function), rest[0] == '1'};
    if (text[0] == 'V')
        if (const auto speed = parseNumber(rest, -HighestSpeed, HighestSpeed))
            return SpeedState{*speed};
    if (text == "R0" || text == "R1")
        return DirectionState{text == "R1"};
    if (text[0] == 's')
        if (const auto mode = parseNumber(rest, 0, 255))
            return SpeedStepState{*mode};
    return std::nullopt;
}

Parsed parseThrottle(std::string_view line) {
    const std::size_t separator = line.find(CommandSeparator);
    if (line.size() < 4 || separator == std::string_view::npos || separator < 4)
        return std::nullopt;
    const char throttle = line[1];
    const std::string key(line.substr(3, separator - 3));
    const std::string_view rest = line.substr(separator + CommandSeparator.size());
    switch (line[2]) {
    case '+':
    case '-':
        if (rest.empty())
            return ThrottleReply{throttle, ThrottleReplyKind(line[2]), key};
        return std::nullopt;
    case 'S':
        if (rest == key)
            return ThrottleReply{throttle, ThrottleReplyKind::StealNeeded, key};
        return std::nullopt;
    case 'L': {
        const Parts labels = split(rest, EntrySeparator);
        if (!labels[0].empty())
            return std::nullopt;
        return FunctionLabels{throttle, key, {labels.begin() + 1, labels.end()}};
    }
    case 'A':
        if (const auto update = parseUpdate(rest))
            return LocoStatus{throttle, key, *update};
        return std::nullopt;
    default:
        return std::nullopt;
    }
}

} // namespace

std::optional<ServerLine> parseServerLine(std::string_view line) {
    if (line.starts_with("VN"))
        return ProtocolVersion{std::string(line.substr(2))};
    if (line.starts_with("RL"))
        return parseRoster(line);
    if (line.starts_with('*'))
        if (const auto seconds = parseNumber(line.substr(1), 0, 3600))
            return HeartbeatInterval{*seconds};
    if (line.starts_with("HT"))
        return ServerType{std::string(line.substr(2))};
    if (line.starts_with("Ht"))
        return ServerDescription{std::string(line.substr(2))};
    if (line.starts_with("HM"))
        return ServerMessage{std::string(line.substr(2))};
    if (line.starts_with('P') && line.size() >= 3)
        return parsePanel(line);
    if (line.starts_with('M'))
        return parseThrottle(line);
    return std::nullopt;
}

} // namespace stellwerk::withrottle
