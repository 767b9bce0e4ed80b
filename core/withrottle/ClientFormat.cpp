#include "withrottle/ClientMessages.h"
#include "withrottle/Text.h"

namespace stellwerk::withrottle {

namespace {

std::string selectionText(const LocoSelection& selection) {
    if (const auto* roster = std::get_if<RosterSelection>(&selection))
        return "E" + cleanText(roster->name);
    return formatLocoAddress(std::get<LocoAddress>(selection));
}

struct ActionFormat {
    std::string operator()(const SetSpeed& a) const { return "V" + std::to_string(a.speed); }
    std::string operator()(const SetDirection& a) const { return a.forward ? "R1" : "R0"; }
    std::string operator()(const FunctionKey& a) const {
        return std::string(a.forced ? "f" : "F") + (a.pressed ? "1" : "0") + std::to_string(a.function);
    }
    std::string operator()(const QuerySpeed&) const { return "qV"; }
    std::string operator()(const QueryDirection&) const { return "qR"; }
    std::string operator()(const EmergencyStop&) const { return "X"; }
    std::string operator()(const Idle&) const { return "I"; }
    std::string operator()(const SetSpeedStepMode& a) const { return "s" + std::to_string(a.mode); }
};

std::string throttlePrefix(char throttle, char command, const std::string& key) {
    return "M" + cleanText({&throttle, 1}) + command + cleanText(key) + std::string(CommandSeparator);
}

struct MessageFormat {
    std::string operator()(const DeviceName& m) const { return "N" + cleanText(m.name); }
    std::string operator()(const HardwareId& m) const { return "HU" + cleanText(m.id); }
    std::string operator()(const ClientVersion& m) const { return "VN" + cleanText(m.version); }
    std::string operator()(const Heartbeat& m) const {
        return m.kind == HeartbeatKind::Beat ? "*" : (m.kind == HeartbeatKind::MonitoringOn ? "*+" : "*-");
    }
    std::string operator()(const SetPower& m) const { return m.on ? "PPA1" : "PPA0"; }
    std::string operator()(const SwitchTurnout& m) const {
        return "PTA" + std::string(1, char(m.action)) + cleanText(m.systemName);
    }
    std::string operator()(const SetRoute& m) const { return "PRA2" + cleanText(m.systemName); }
    std::string operator()(const Quit&) const { return "Q"; }
    std::string operator()(const AcquireLoco& m) const {
        return throttlePrefix(m.throttle, m.steal ? 'S' : '+', m.key) + selectionText(m.selection);
    }
    std::string operator()(const ReleaseLoco& m) const {
        return throttlePrefix(m.throttle, '-', m.key) + (m.dispatch ? "d" : "r");
    }
    std::string operator()(const ThrottleAction& m) const {
        return throttlePrefix(m.throttle, 'A', m.key) + std::visit(ActionFormat{}, m.action);
    }
    std::string operator()(const UnknownLine& m) const { return cleanText(m.line); }
};

} // namespace

std::string formatClientLine(const ClientMessage& message) {
    return std::visit(MessageFormat{}, message);
}

} // namespace stellwerk::withrottle
