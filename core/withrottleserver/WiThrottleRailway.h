#pragma once

#include "withrottle/ClientMessages.h"
#include "withrottle/ServerLines.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::model {
class Railway;
class Z21Addresses;
} // namespace stellwerk::model

namespace stellwerk::withrottleserver {

// The railway in WiThrottle terms, the one place where the server's names and numbers meet the model:
// locomotives on the addresses of the Z21 address book (a DCC locomotive its own, MM and mfx ones the
// book's, so that a phone shows the same number in the Z21 app and in Engine Driver; S up to 127, L above),
// turnouts as the railway's accessories by keyboard number ("MT<n>", position 0 = round = thrown), routes
// as the layout's fahrstrassen ("MR<id>"), speeds 0..126 against the station's 0..1000.
class WiThrottleRailway {
public:
    WiThrottleRailway(model::Railway& railway, model::Z21Addresses& addresses);

    model::Railway& railway() const { return railway_; }
    // Gives every MM and mfx locomotive of the railway an address it lacks.
    void coverLocomotives();

    withrottle::RosterList roster() const;
    // The locomotive an acquire names, by address or roster entry.
    std::optional<std::uint32_t> locoFor(const withrottle::LocoSelection& selection) const;
    std::optional<withrottle::LocoAddress> addressOf(std::uint32_t locId) const;
    // F0..F31: "F<n>" for each function the locomotive has, empty (a key the phone hides) for the others;
    // a locomotive lokomotive.cs2 tells nothing about gets every key.
    std::vector<std::string> functionLabels(std::uint32_t locId) const;
    // A momentary key is on while pressed; every other key changes on a press (the server decides, as
    // JMRI's protocol page says).
    bool isMomentary(std::uint32_t locId, int function) const;

    withrottle::TurnoutList turnouts() const;
    withrottle::TurnoutState turnoutState(std::int64_t keyboard) const;
    std::optional<std::int64_t> turnoutOf(const std::string& systemName) const;
    static std::string turnoutName(std::int64_t keyboard);
    void switchTurnout(std::int64_t keyboard, withrottle::TurnoutAction action);

    withrottle::RouteList routes() const;
    withrottle::RouteState routeState(std::int64_t route) const;
    std::optional<std::int64_t> routeOf(const std::string& systemName) const;
    static std::string routeName(std::int64_t route);

    // Unknown while the station is not heard or has not told it.
    withrottle::PowerState power() const;

    static int systemSpeed(int throttleSpeed); // 0..126 -> 0..1000
    static int throttleSpeed(int systemSpeed); // 0..1000 -> 0..126

private:
    std::vector<std::uint32_t> locIds() const;

    model::Railway& railway_;
    model::Z21Addresses& addresses_;
};

} // namespace stellwerk::withrottleserver
