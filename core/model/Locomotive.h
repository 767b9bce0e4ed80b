#pragma once

#include "cs2/LocId.h"
#include "cs2/Messages.h"
#include "cs2config/Locomotive.h"

#include <QString>
#include <cstdint>
#include <vector>

namespace stellwerk::model {

// One function key of a locomotive as a throttle shows it: its icon, how it triggers, whether it is on.
struct LocomotiveFunction {
    int number = 0;
    int icon = 0; // the CS2 icon number (`..typ`)
    cs2config::FunctionTrigger trigger = cs2config::FunctionTrigger::Latching;
    bool on = false;
};

// A locomotive as the throttles show it: what lokomotive.cs2 says about it, plus the speed, direction
// and function states the station last confirmed.
class Locomotive {
public:
    static constexpr std::uint16_t MaxSpeed = 1000;
    static constexpr int MaxFunctions = 32;

    Locomotive() = default;
    // A locomotive seen on the bus but not in lokomotive.cs2 (another controller drives it).
    explicit Locomotive(cs2::LocId id);
    // From a lokomotive.cs2 record; the saved speed, direction and function values are the start state.
    static Locomotive fromFile(const cs2config::Locomotive& record);

    cs2::LocId id() const { return id_; }
    const QString& name() const { return name_; }
    // The name to show: the file's name, or "DCC 3" for a locomotive without one.
    QString displayName() const;
    cs2config::LocomotiveDecoder decoder() const { return decoder_; }
    bool inLayout() const { return inLayout_; }
    const std::vector<LocomotiveFunction>& functions() const { return functions_; }
    const LocomotiveFunction* function(int number) const;

    std::uint16_t speed() const { return speed_; }
    cs2::Direction direction() const { return direction_; }
    bool functionOn(int number) const;

    // Confirmed changes; each returns true when the state changed.
    bool confirmSpeed(std::uint16_t speed);
    // A direction the bus reported; a change also means speed 0: the station stops the locomotive on a
    // direction change and does not say so (field notes).
    bool confirmDirection(cs2::Direction direction);
    // The station acknowledged a direction command: it stopped the locomotive, even for the same direction.
    bool directionSet(cs2::Direction direction);
    bool confirmFunction(int number, bool on);
    // Takes over what the bus already confirmed about this locomotive (when the file arrives later).
    void keepConfirmedState(const Locomotive& seen);

private:
    cs2::LocId id_;
    QString name_;
    cs2config::LocomotiveDecoder decoder_ = cs2config::LocomotiveDecoder::None;
    bool inLayout_ = false;
    std::vector<LocomotiveFunction> functions_;
    std::uint16_t speed_ = 0;
    cs2::Direction direction_ = cs2::Direction::Forward;
    bool speedConfirmed_ = false;
    bool directionConfirmed_ = false;
    std::uint32_t functionsConfirmed_ = 0; // bit n: Fn was confirmed
};

} // namespace stellwerk::model
