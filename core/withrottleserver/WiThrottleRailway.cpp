#include "withrottleserver/WiThrottleRailway.h"

#include "model/Railway.h"
#include "model/Z21Addresses.h"
#include "withrottle/Text.h"

#include <algorithm>
#include <cmath>

namespace stellwerk::withrottleserver {
namespace {

constexpr int ShortAddressLimit = 127;
constexpr std::string_view TurnoutPrefix = "MT";
constexpr std::string_view RoutePrefix = "MR";

std::optional<std::int64_t> numberAfter(std::string_view prefix, const std::string& name) {
    if (!name.starts_with(prefix))
        return std::nullopt;
    const auto number = withrottle::parseNumber(std::string_view(name).substr(prefix.size()), 1, 0x7FFFFFFF);
    return number ? std::optional<std::int64_t>(*number) : std::nullopt;
}

} // namespace

WiThrottleRailway::WiThrottleRailway(model::Railway& railway, model::Z21Addresses& addresses)
    : railway_(railway), addresses_(addresses) {}

std::vector<std::uint32_t> WiThrottleRailway::locIds() const {
    std::vector<std::uint32_t> ids;
    for (const model::Locomotive& loco : railway_.state().locomotives().items())
        ids.push_back(loco.id().value());
    return ids;
}

void WiThrottleRailway::coverLocomotives() {
    addresses_.cover(locIds());
}

withrottle::RosterList WiThrottleRailway::roster() const {
    withrottle::RosterList list;
    for (const model::Locomotive& loco : railway_.state().locomotives().items())
        if (const auto address = addressOf(loco.id().value()))
            list.entries.push_back({loco.displayName().toStdString(), *address});
    return list;
}

std::optional<std::uint32_t> WiThrottleRailway::locoFor(const withrottle::LocoSelection& selection) const {
    if (const auto* address = std::get_if<withrottle::LocoAddress>(&selection)) {
        if (address->number == 0)
            return std::nullopt;
        return addresses_.locoAt(address->number, locIds());
    }
    const std::string& name = std::get<withrottle::RosterSelection>(selection).name;
    for (const model::Locomotive& loco : railway_.state().locomotives().items())
        if (withrottle::cleanText(loco.displayName().toStdString()) == name ||
            loco.displayName().toStdString() == name)
            return loco.id().value();
    return std::nullopt;
}

std::optional<withrottle::LocoAddress> WiThrottleRailway::addressOf(std::uint32_t locId) const {
    const std::optional<std::uint16_t> number = addresses_.addressOf(locId);
    if (!number)
        return std::nullopt;
    return withrottle::LocoAddress{*number, *number > ShortAddressLimit};
}

std::vector<std::string> WiThrottleRailway::functionLabels(std::uint32_t locId) const {
    std::vector<std::string> labels(withrottle::HighestFunction + 1);
    const model::Locomotive* loco = railway_.locomotive(locId);
    const bool toldNothing = !loco || loco->functions().empty();
    for (int number = 0; number <= withrottle::HighestFunction; ++number)
        if (toldNothing || (loco && loco->function(number)))
            labels[std::size_t(number)] = "F" + std::to_string(number);
    return labels;
}

bool WiThrottleRailway::isMomentary(std::uint32_t locId, int function) const {
    const model::Locomotive* loco = railway_.locomotive(locId);
    const model::LocomotiveFunction* key = loco ? loco->function(function) : nullptr;
    return key && key->trigger == cs2config::FunctionTrigger::Momentary;
}

withrottle::TurnoutList WiThrottleRailway::turnouts() const {
    withrottle::TurnoutList list;
    for (const model::Accessory& accessory : railway_.state().accessories().items()) {
        if (accessory.positionCount() != 2)
            continue;
        const std::string name =
            accessory.name().isEmpty() ? turnoutName(accessory.id()) : accessory.name().toStdString();
        list.turnouts.push_back({turnoutName(accessory.id()), name, turnoutState(accessory.id())});
    }
    return list;
}

withrottle::TurnoutState WiThrottleRailway::turnoutState(std::int64_t keyboard) const {
    const model::Accessory* accessory = railway_.accessory(keyboard);
    if (!accessory || !accessory->isPositionReported() || !railway_.isStateReported())
        return withrottle::TurnoutState::Unknown;
    return accessory->position() == 0 ? withrottle::TurnoutState::Thrown : withrottle::TurnoutState::Closed;
}

std::optional<std::int64_t> WiThrottleRailway::turnoutOf(const std::string& systemName) const {
    const std::optional<std::int64_t> keyboard = numberAfter(TurnoutPrefix, systemName);
    const model::Accessory* accessory = keyboard ? railway_.accessory(*keyboard) : nullptr;
    if (!accessory || accessory->positionCount() != 2)
        return std::nullopt;
    return keyboard;
}

std::string WiThrottleRailway::turnoutName(std::int64_t keyboard) {
    return std::string(TurnoutPrefix) + std::to_string(keyboard);
}

// Thrown is position 0 (round, red), closed position 1 (straight, green); a toggle of a turnout whose
// position is not known throws it.
void WiThrottleRailway::switchTurnout(std::int64_t keyboard, withrottle::TurnoutAction action) {
    int position = action == withrottle::TurnoutAction::Close ? 1 : 0;
    if (action == withrottle::TurnoutAction::Toggle)
        position = turnoutState(keyboard) == withrottle::TurnoutState::Thrown ? 1 : 0;
    railway_.switchAccessory(keyboard, position);
}

withrottle::RouteList WiThrottleRailway::routes() const {
    withrottle::RouteList list;
    for (const model::Route& route : railway_.state().routes().items())
        list.routes.push_back({routeName(route.id()), route.name().toStdString(), routeState(route.id())});
    return list;
}

withrottle::RouteState WiThrottleRailway::routeState(std::int64_t route) const {
    if (!railway_.isStateReported())
        return withrottle::RouteState::Unknown;
    return railway_.isRouteSet(route) ? withrottle::RouteState::Active : withrottle::RouteState::Inactive;
}

std::optional<std::int64_t> WiThrottleRailway::routeOf(const std::string& systemName) const {
    const std::optional<std::int64_t> id = numberAfter(RoutePrefix, systemName);
    if (!id || !railway_.route(*id))
        return std::nullopt;
    return id;
}

std::string WiThrottleRailway::routeName(std::int64_t route) {
    return std::string(RoutePrefix) + std::to_string(route);
}

withrottle::PowerState WiThrottleRailway::power() const {
    if (!railway_.throttlePort().canDrive())
        return withrottle::PowerState::Unknown;
    const std::optional<bool> on = railway_.throttlePort().powerOn();
    if (!on)
        return withrottle::PowerState::Unknown;
    return *on ? withrottle::PowerState::On : withrottle::PowerState::Off;
}

int WiThrottleRailway::systemSpeed(int throttleSpeed) {
    const int clamped = std::clamp(throttleSpeed, 0, withrottle::HighestSpeed);
    return int(std::lround(clamped * double(model::Locomotive::MaxSpeed) / withrottle::HighestSpeed));
}

int WiThrottleRailway::throttleSpeed(int systemSpeed) {
    const int clamped = std::clamp(systemSpeed, 0, int(model::Locomotive::MaxSpeed));
    return int(std::lround(clamped * double(withrottle::HighestSpeed) / model::Locomotive::MaxSpeed));
}

} // namespace stellwerk::withrottleserver
