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
    int icon = 0; // the CS2 icon number (`..typ`); bit 7 marks a momentary key (see momentaryIconBit)
    cs2config::FunctionTrigger trigger = cs2config::FunctionTrigger::Latching;
    bool on = false;
    int duration = 0; // a timed key's `..dauer` as written (the document names no unit), else 0
};

// A locomotive as the throttles show it: what lokomotive.cs2 says about it, plus the speed, direction
// and function states the station last confirmed.
class Locomotive {
public:
    static constexpr std::uint16_t MaxSpeed = 1000;
    static constexpr int MaxFunctions = 32;
    // A CS2 writes a momentary key as its icon number plus 128 when `..dauer` does not say otherwise.
    static constexpr int MomentaryIconBit = 0x80;

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
    // The track address and protocol the station drives it with (from its Loc-ID).
    std::uint32_t address() const { return id_.address(); }
    cs2::Protocol protocol() const { return id_.protocol(); }
    // The speedometer's full scale in km/h (`.tachomax`); 0 when the file gives none.
    int tachoMax() const { return tachoMax_; }
    // The station's picture of the locomotive (`.icon`, a file name without extension); may be empty.
    const QString& iconName() const { return iconName_; }
    bool inLayout() const { return inLayout_; }
    const std::vector<LocomotiveFunction>& functions() const { return functions_; }
    const LocomotiveFunction* function(int number) const;

    std::uint16_t speed() const { return speed_; }
    cs2::Direction direction() const { return direction_; }
    bool functionOn(int number) const;

    // Whether the station reported the value shown now (since the model's state was last lost, see
    // Railway::isStateReported). False means the value is the file's or the one last reported before the
    // station fell silent or the connection was lost, and a view shows it as "not reported". After a
    // reconnect, a speed query that got no answer leaves isSpeedReported() false.
    bool isSpeedReported() const { return speedConfirmed_; }
    bool isDirectionReported() const { return directionConfirmed_; }
    bool isFunctionReported(int number) const;
    // The station can no longer be heard: every value becomes "not reported" (and stays as it was).
    void forgetReported();

    // Confirmed changes; each returns true when the state changed or became reported.
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
    int tachoMax_ = 0;
    QString iconName_;
    std::vector<LocomotiveFunction> functions_;
    std::uint16_t speed_ = 0;
    cs2::Direction direction_ = cs2::Direction::Forward;
    bool speedConfirmed_ = false;
    bool directionConfirmed_ = false;
    std::uint32_t functionsConfirmed_ = 0; // bit n: Fn was confirmed
};

} // namespace stellwerk::model
