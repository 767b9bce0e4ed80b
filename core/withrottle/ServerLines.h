#pragma once

#include "withrottle/ClientMessages.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace stellwerk::withrottle {

// The lines a WiThrottle server sends (JMRI's protocol page: "Initial Connection", "Property Change
// Notification", the multithrottle replies, "Observations").

struct ProtocolVersion { // VN2.0
    std::string version = "2.0";
    bool operator==(const ProtocolVersion&) const = default;
};
struct RosterEntry {
    std::string name;
    LocoAddress address;
    bool operator==(const RosterEntry&) const = default;
};
struct RosterList { // RL<n>]\[name}|{address}|{S|L...
    std::vector<RosterEntry> entries;
    bool operator==(const RosterList&) const = default;
};
enum class PowerState : char { Off = '0', On = '1', Unknown = '2' };
struct PowerStatus { // PPA0 / PPA1 / PPA2
    PowerState state = PowerState::Unknown;
    bool operator==(const PowerStatus&) const = default;
};
// The turnout states of PTT and PTL; 1 (unknown) has no caption.
enum class TurnoutState : std::uint8_t { Unknown = 1, Closed = 2, Thrown = 4 };
struct TurnoutTitles { // PTT]\[Turnouts}|{Turnout]\[Closed}|{2]\[Thrown}|{4
    std::string title = "Turnouts";
    std::string singular = "Turnout";
    std::string closed = "Closed";
    std::string thrown = "Thrown";
    bool operator==(const TurnoutTitles&) const = default;
};
struct TurnoutEntry {
    std::string systemName;
    std::string userName;
    TurnoutState state = TurnoutState::Unknown;
    bool operator==(const TurnoutEntry&) const = default;
};
struct TurnoutList { // PTL]\[system}|{user}|{state...
    std::vector<TurnoutEntry> turnouts;
    bool operator==(const TurnoutList&) const = default;
};
struct TurnoutChanged { // PTA<state><system name>
    std::string systemName;
    TurnoutState state = TurnoutState::Unknown;
    bool operator==(const TurnoutChanged&) const = default;
};
enum class RouteState : std::uint8_t { Unknown = 1, Active = 2, Inactive = 4 };
struct RouteTitles { // PRT]\[Routes}|{Route]\[Active}|{2]\[Inactive}|{4
    std::string title = "Routes";
    std::string singular = "Route";
    std::string active = "Active";
    std::string inactive = "Inactive";
    bool operator==(const RouteTitles&) const = default;
};
struct RouteEntry {
    std::string systemName;
    std::string userName;
    std::optional<RouteState> state; // the page's example leaves it empty
    bool operator==(const RouteEntry&) const = default;
};
struct RouteList { // PRL]\[system}|{user}|{state...
    std::vector<RouteEntry> routes;
    bool operator==(const RouteList&) const = default;
};
struct RouteChanged { // PRA<state><system name>
    std::string systemName;
    RouteState state = RouteState::Unknown;
    bool operator==(const RouteChanged&) const = default;
};
struct WebPort { // PW<port>
    std::uint16_t port = 0;
    bool operator==(const WebPort&) const = default;
};
struct HeartbeatInterval { // *<seconds>, 0 = no heartbeat needed
    int seconds = 10;
    bool operator==(const HeartbeatInterval&) const = default;
};
struct ServerType { // HT<type>
    std::string text;
    bool operator==(const ServerType&) const = default;
};
struct ServerDescription { // Ht<description>
    std::string text;
    bool operator==(const ServerDescription&) const = default;
};
struct ServerMessage { // HM<message>
    std::string text;
    bool operator==(const ServerMessage&) const = default;
};

// The multithrottle's answers: M<t>+<key><;> added, M<t>-<key><;> removed, M<t>S<key><;><key> steal needed.
enum class ThrottleReplyKind : char { Added = '+', Removed = '-', StealNeeded = 'S' };
struct ThrottleReply {
    char throttle = 'T';
    ThrottleReplyKind kind = ThrottleReplyKind::Added;
    std::string key;
    bool operator==(const ThrottleReply&) const = default;
};
// M<t>L<key><;>]\[F0 label]\[F1 label...
struct FunctionLabels {
    char throttle = 'T';
    std::string key;
    std::vector<std::string> labels;
    bool operator==(const FunctionLabels&) const = default;
};
// What M<t>A<key><;>... tells of a loco: F<0|1><n>, V<speed> (negative: emergency stop), R<0|1>, s<mode>.
struct FunctionState {
    std::uint8_t function = 0;
    bool on = false;
    bool operator==(const FunctionState&) const = default;
};
struct SpeedState {
    int speed = 0;
    bool operator==(const SpeedState&) const = default;
};
struct DirectionState {
    bool forward = true;
    bool operator==(const DirectionState&) const = default;
};
struct SpeedStepState {
    int mode = 1;
    bool operator==(const SpeedStepState&) const = default;
};
using LocoUpdate = std::variant<FunctionState, SpeedState, DirectionState, SpeedStepState>;
struct LocoStatus {
    char throttle = 'T';
    std::string key;
    LocoUpdate update;
    bool operator==(const LocoStatus&) const = default;
};

using ServerLine =
    std::variant<ProtocolVersion, RosterList, PowerStatus, TurnoutTitles, TurnoutList, TurnoutChanged,
                 RouteTitles, RouteList, RouteChanged, WebPort, HeartbeatInterval, ServerType,
                 ServerDescription, ServerMessage, ThrottleReply, FunctionLabels, LocoStatus>;

// A line as the server sends it, without the line end; texts cleaned (withrottle::cleanText).
std::string formatServerLine(const ServerLine& line);
// A server line (what a client reads; for tests and test clients); nullopt for a line it does not read.
std::optional<ServerLine> parseServerLine(std::string_view line);

} // namespace stellwerk::withrottle
