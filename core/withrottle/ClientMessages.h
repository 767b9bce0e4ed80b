#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace stellwerk::withrottle {

// The lines a WiThrottle client (Engine Driver, WiThrottle) sends, as JMRI's protocol page
// (help/en/package/jmri/jmrit/withrottle/Protocol.shtml) describes them; section names are the page's.

// A DCC address as the protocol writes it: S3 (short) or L341 (long).
struct LocoAddress {
    std::uint16_t number = 0;
    bool longAddress = false;
    bool operator==(const LocoAddress&) const = default;
};
std::optional<LocoAddress> parseLocoAddress(std::string_view text);
std::string formatLocoAddress(const LocoAddress& address);

// A roster entry chosen by its name: E<name> ("'E' sets an address from a roster entry").
struct RosterSelection {
    std::string name;
    bool operator==(const RosterSelection&) const = default;
};
using LocoSelection = std::variant<LocoAddress, RosterSelection>;

struct DeviceName { // 'N' Device Name; the server answers *<seconds>
    std::string name;
    bool operator==(const DeviceName&) const = default;
};
struct HardwareId { // 'H' Hardware Information: HU<id>
    std::string id;
    bool operator==(const HardwareId&) const = default;
};
struct ClientVersion { // VN<version>
    std::string version;
    bool operator==(const ClientVersion&) const = default;
};
enum class HeartbeatKind : std::uint8_t { Beat, MonitoringOn, MonitoringOff };
struct Heartbeat { // '*' Heartbeat: *, *+, *-
    HeartbeatKind kind = HeartbeatKind::Beat;
    bool operator==(const Heartbeat&) const = default;
};
struct SetPower { // PPA0 / PPA1
    bool on = false;
    bool operator==(const SetPower&) const = default;
};
enum class TurnoutAction : char { Close = 'C', Throw = 'T', Toggle = '2' };
struct SwitchTurnout { // PTA<C|T|2><system name>
    TurnoutAction action = TurnoutAction::Toggle;
    std::string systemName;
    bool operator==(const SwitchTurnout&) const = default;
};
struct SetRoute { // PRA2<system name>
    std::string systemName;
    bool operator==(const SetRoute&) const = default;
};
struct Quit { // 'Q': the device has quit
    bool operator==(const Quit&) const = default;
};

// M<t>+<key><;><S3|L341|E<name>> (add a locomotive), or M<t>S... (steal one the server said is taken).
struct AcquireLoco {
    char throttle = 'T';
    std::string key;
    LocoSelection selection;
    bool steal = false;
    bool operator==(const AcquireLoco&) const = default;
};
// M<t>-<key|*><;>r (release) or d (dispatch); "*" is every loco of the throttle.
struct ReleaseLoco {
    char throttle = 'T';
    std::string key;
    bool dispatch = false;
    bool operator==(const ReleaseLoco&) const = default;
};

// The throttle controller commands of an action M<t>A<key|*><;>...
struct SetSpeed { // V0..V126
    int speed = 0;
    bool operator==(const SetSpeed&) const = default;
};
struct SetDirection { // R0 reverse, R1 forward
    bool forward = true;
    bool operator==(const SetDirection&) const = default;
};
struct FunctionKey { // F1<n> pressed, F0<n> released (the server decides latching); f<0|1><n> forced
    std::uint8_t function = 0;
    bool pressed = false;
    bool forced = false;
    bool operator==(const FunctionKey&) const = default;
};
struct QuerySpeed { // qV
    bool operator==(const QuerySpeed&) const = default;
};
struct QueryDirection { // qR
    bool operator==(const QueryDirection&) const = default;
};
struct EmergencyStop { // X
    bool operator==(const EmergencyStop&) const = default;
};
struct Idle { // I: speed 0
    bool operator==(const Idle&) const = default;
};
struct SetSpeedStepMode { // s<mode>: 1 = 128 steps, 2 = 28, 4 = 27, 8 = 14, 16 = 28 (Motorola)
    int mode = 1;
    bool operator==(const SetSpeedStepMode&) const = default;
};
using LocoAction = std::variant<SetSpeed, SetDirection, FunctionKey, QuerySpeed, QueryDirection,
                                EmergencyStop, Idle, SetSpeedStepMode>;
struct ThrottleAction {
    char throttle = 'T';
    std::string key;
    LocoAction action;
    bool operator==(const ThrottleAction&) const = default;
};

// Anything else: "any command that is not recognized ... should be ignored".
struct UnknownLine {
    std::string line;
    bool operator==(const UnknownLine&) const = default;
};

using ClientMessage = std::variant<DeviceName, HardwareId, ClientVersion, Heartbeat, SetPower, SwitchTurnout,
                                   SetRoute, Quit, AcquireLoco, ReleaseLoco, ThrottleAction, UnknownLine>;

// The highest function a client may name (F0..F31, as the station has).
inline constexpr int HighestFunction = 31;
// The highest speed of V (126 steps).
inline constexpr int HighestSpeed = 126;

// One line (without its line end) as a message; never fails: what it does not read is an UnknownLine.
ClientMessage parseClientLine(std::string_view line);
// A message as the line a client sends, without the line end (for tests and test clients). Texts are
// cleaned (withrottle::cleanText), so that a name cannot end the line or break the delimiters.
std::string formatClientLine(const ClientMessage& message);

} // namespace stellwerk::withrottle
