#include "withrottle/ServerLines.h"
#include "withrottle/Text.h"

namespace stellwerk::withrottle {

namespace {

const std::string Entry(EntrySeparator);
const std::string Part(PartSeparator);

std::string digit(std::uint8_t value) {
    return std::to_string(value);
}

std::string titles(const char* prefix, const std::string& title, const std::string& singular,
                   const std::string& on, const std::string& off) {
    return prefix + Entry + cleanText(title) + Part + cleanText(singular) + Entry + cleanText(on) + Part +
           "2" + Entry + cleanText(off) + Part + "4";
}

std::string throttlePrefix(char throttle, char command, const std::string& key) {
    return "M" + cleanText({&throttle, 1}) + command + cleanText(key) + std::string(CommandSeparator);
}

struct UpdateFormat {
    std::string operator()(const FunctionState& u) const {
        return std::string("F") + (u.on ? "1" : "0") + std::to_string(u.function);
    }
    std::string operator()(const SpeedState& u) const { return "V" + std::to_string(u.speed); }
    std::string operator()(const DirectionState& u) const { return u.forward ? "R1" : "R0"; }
    std::string operator()(const SpeedStepState& u) const { return "s" + std::to_string(u.mode); }
};

struct LineFormat {
    std::string operator()(const ProtocolVersion& l) const { return "VN" + cleanText(l.version); }
    std::string operator()(const RosterList& l) const {
        std::string line = "RL" + std::to_string(l.entries.size());
        for (const RosterEntry& e : l.entries)
            line += Entry + cleanText(e.name) + Part + std::to_string(e.address.number) + Part +
                    (e.address.longAddress ? "L" : "S");
        return line;
    }
    std::string operator()(const PowerStatus& l) const { return "PPA" + std::string(1, char(l.state)); }
    std::string operator()(const TurnoutTitles& l) const {
        return titles("PTT", l.title, l.singular, l.closed, l.thrown);
    }
    std::string operator()(const TurnoutList& l) const {
        std::string line = "PTL";
        for (const TurnoutEntry& t : l.turnouts)
            line += Entry + cleanText(t.systemName) + Part + cleanText(t.userName) + Part +
                    digit(std::uint8_t(t.state));
        return line;
    }
    std::string operator()(const TurnoutChanged& l) const {
        return "PTA" + digit(std::uint8_t(l.state)) + cleanText(l.systemName);
    }
    std::string operator()(const RouteTitles& l) const {
        return titles("PRT", l.title, l.singular, l.active, l.inactive);
    }
    std::string operator()(const RouteList& l) const {
        std::string line = "PRL";
        for (const RouteEntry& r : l.routes)
            line += Entry + cleanText(r.systemName) + Part + cleanText(r.userName) + Part +
                    (r.state ? digit(std::uint8_t(*r.state)) : "");
        return line;
    }
    std::string operator()(const RouteChanged& l) const {
        return "PRA" + digit(std::uint8_t(l.state)) + cleanText(l.systemName);
    }
    std::string operator()(const WebPort& l) const { return "PW" + std::to_string(l.port); }
    std::string operator()(const HeartbeatInterval& l) const { return "*" + std::to_string(l.seconds); }
    std::string operator()(const ServerType& l) const { return "HT" + cleanText(l.text); }
    std::string operator()(const ServerDescription& l) const { return "Ht" + cleanText(l.text); }
    std::string operator()(const ServerMessage& l) const { return "HM" + cleanText(l.text); }
    std::string operator()(const ThrottleReply& l) const {
        const std::string line = throttlePrefix(l.throttle, char(l.kind), l.key);
        return l.kind == ThrottleReplyKind::StealNeeded ? line + cleanText(l.key) : line;
    }
    std::string operator()(const FunctionLabels& l) const {
        std::string line = throttlePrefix(l.throttle, 'L', l.key);
        for (const std::string& label : l.labels)
            line += Entry + cleanText(label);
        return line;
    }
    std::string operator()(const LocoStatus& l) const {
        return throttlePrefix(l.throttle, 'A', l.key) + std::visit(UpdateFormat{}, l.update);
    }
};

} // namespace

std::string formatServerLine(const ServerLine& line) {
    return std::visit(LineFormat{}, line);
}

} // namespace stellwerk::withrottle
