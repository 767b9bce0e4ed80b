#include "withrottle/ClientMessages.h"
#include "withrottle/Text.h"

namespace stellwerk::withrottle {

namespace {

using Parsed = std::optional<ClientMessage>;

std::optional<LocoSelection> parseSelection(std::string_view text) {
    if (text.starts_with('E') && text.size() > 1)
        return RosterSelection{std::string(text.substr(1))};
    if (const auto address = parseLocoAddress(text))
        return *address;
    return std::nullopt;
}

std::optional<FunctionKey> parseFunction(std::string_view text, bool forced) {
    if (text.size() < 2 || (text[0] != '0' && text[0] != '1'))
        return std::nullopt;
    const auto number = parseNumber(text.substr(1), 0, HighestFunction);
    if (!number)
        return std::nullopt;
    return FunctionKey{std::uint8_t(*number), text[0] == '1', forced};
}

std::optional<LocoAction> parseAction(std::string_view text) {
    if (text == "qV")
        return QuerySpeed{};
    if (text == "qR")
        return QueryDirection{};
    if (text == "X")
        return EmergencyStop{};
    if (text == "I")
        return Idle{};
    if (text.empty())
        return std::nullopt;
    const std::string_view rest = text.substr(1);
    switch (text[0]) {
    case 'V':
        if (const auto speed = parseNumber(rest, 0, HighestSpeed))
            return SetSpeed{*speed};
        return std::nullopt;
    case 'R':
        if (rest.size() == 1 && rest[0] >= '0' && rest[0] <= '9')
            return SetDirection{rest[0] != '0'};
        return std::nullopt;
    case 's':
        if (const auto mode = parseNumber(rest, 0, 255))
            return SetSpeedStepMode{*mode};
        return std::nullopt;
    case 'F':
    case 'f':
        if (const auto key = parseFunction(rest, text[0] == 'f'))
            return *key;
        return std::nullopt;
    default:
        return std::nullopt;
    }
}

// M<t><command><key><;><argument>
Parsed parseThrottle(std::string_view line) {
    const std::size_t separator = line.find(CommandSeparator);
    if (line.size() < 4 || separator == std::string_view::npos || separator < 4)
        return std::nullopt;
    const char throttle = line[1];
    const std::string key(line.substr(3, separator - 3));
    const std::string_view argument = line.substr(separator + CommandSeparator.size());
    switch (line[2]) {
    case '+':
    case 'S':
        if (const auto selection = parseSelection(argument))
            return AcquireLoco{throttle, key, *selection, line[2] == 'S'};
        return std::nullopt;
    case '-':
        if (argument == "r" || argument == "d")
            return ReleaseLoco{throttle, key, argument == "d"};
        return std::nullopt;
    case 'A':
        if (const auto action = parseAction(argument))
            return ThrottleAction{throttle, key, *action};
        return std::nullopt;
    default:
        return std::nullopt;
    }
}

Parsed parsePanel(std::string_view line) {
    if (line == "PPA0" || line == "PPA1")
        return SetPower{line[3] == '1'};
    if (line.size() > 4 && line.starts_with("PTA")) {
        const char action = line[3];
        if (action == 'C' || action == 'T' || action == '2')
            return SwitchTurnout{TurnoutAction(action), std::string(line.substr(4))};
    }
    if (line.size() > 4 && line.starts_with("PRA2"))
        return SetRoute{std::string(line.substr(4))};
    return std::nullopt;
}

Parsed parseKnown(std::string_view line) {
    if (line == "*")
        return Heartbeat{HeartbeatKind::Beat};
    if (line == "*+")
        return Heartbeat{HeartbeatKind::MonitoringOn};
    if (line == "*-")
        return Heartbeat{HeartbeatKind::MonitoringOff};
    if (line == "Q")
        return Quit{};
    if (line.size() > 1 && line[0] == 'N')
        return DeviceName{std::string(line.substr(1))};
    if (line.size() > 2 && line.starts_with("HU"))
        return HardwareId{std::string(line.substr(2))};
    if (line.size() > 2 && line.starts_with("VN"))
        return ClientVersion{std::string(line.substr(2))};
    if (line.starts_with('P'))
        return parsePanel(line);
    if (line.starts_with('M'))
        return parseThrottle(line);
    return std::nullopt;
}

} // namespace

std::optional<LocoAddress> parseLocoAddress(std::string_view text) {
    if (text.size() < 2 || (text[0] != 'S' && text[0] != 'L'))
        return std::nullopt;
    const auto number = parseNumber(text.substr(1), 0, 10239);
    if (!number)
        return std::nullopt;
    return LocoAddress{std::uint16_t(*number), text[0] == 'L'};
}

std::string formatLocoAddress(const LocoAddress& address) {
    return (address.longAddress ? "L" : "S") + std::to_string(address.number);
}

ClientMessage parseClientLine(std::string_view line) {
    if (auto message = parseKnown(line))
        return std::move(*message);
    return UnknownLine{std::string(line)};
}

} // namespace stellwerk::withrottle
