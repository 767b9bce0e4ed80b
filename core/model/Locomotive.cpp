#include "model/Locomotive.h"

#include <algorithm>
#include <utility>

namespace stellwerk::model {
namespace {

// `..dauer` decides when it is written; without it, icon bit 7 marks a momentary key (CS2 files).
cs2config::FunctionTrigger triggerOf(const cs2config::Function& f) {
    const cs2config::FunctionTrigger trigger = f.trigger();
    if (trigger == cs2config::FunctionTrigger::Latching && (f.icon & Locomotive::MomentaryIconBit) != 0)
        return cs2config::FunctionTrigger::Momentary;
    return trigger;
}

} // namespace

Locomotive::Locomotive(cs2::LocId id) : id_(id) {}

Locomotive Locomotive::fromFile(const cs2config::Locomotive& record) {
    Locomotive loco{cs2::LocId(record.uid)};
    loco.name_ = QString::fromStdString(record.name);
    loco.decoder_ = record.decoder;
    loco.inLayout_ = true;
    loco.tachoMax_ = std::max(record.tachoMax, 0);
    loco.iconName_ = QString::fromStdString(record.icon);
    loco.speed_ = std::uint16_t(std::clamp(record.velocity, 0, int(MaxSpeed)));
    loco.direction_ = record.direction == cs2config::TravelDirection::Backward ? cs2::Direction::Backward
                                                                               : cs2::Direction::Forward;
    for (const cs2config::Function& f : record.functions) {
        if (f.number < 0 || f.number >= MaxFunctions)
            continue;
        loco.functions_.push_back({f.number, f.icon, triggerOf(f), f.value != 0, f.timedValue()});
    }
    std::ranges::sort(loco.functions_, {}, &LocomotiveFunction::number);
    return loco;
}

QString Locomotive::displayName() const {
    if (!name_.isEmpty())
        return name_;
    const auto protocol = cs2::protocolName(id_.protocol());
    return QStringLiteral("%1 %2")
        .arg(QString::fromLatin1(protocol.data(), qsizetype(protocol.size())).toUpper())
        .arg(id_.address());
}

const LocomotiveFunction* Locomotive::function(int number) const {
    const auto it = std::ranges::find(functions_, number, &LocomotiveFunction::number);
    return it == functions_.end() ? nullptr : &*it;
}

bool Locomotive::functionOn(int number) const {
    const LocomotiveFunction* f = function(number);
    return f && f->on;
}

bool Locomotive::isFunctionReported(int number) const {
    return number >= 0 && number < MaxFunctions && (functionsConfirmed_ >> number & 1U) != 0;
}

void Locomotive::forgetReported() {
    speedConfirmed_ = false;
    directionConfirmed_ = false;
    functionsConfirmed_ = 0;
}

bool Locomotive::confirmSpeed(std::uint16_t speed) {
    speed = std::min(speed, MaxSpeed);
    const bool newlyReported = !std::exchange(speedConfirmed_, true);
    if (speed == speed_)
        return newlyReported;
    speed_ = speed;
    return true;
}

bool Locomotive::confirmDirection(cs2::Direction direction) {
    if (direction == cs2::Direction::Toggle)
        direction =
            direction_ == cs2::Direction::Forward ? cs2::Direction::Backward : cs2::Direction::Forward;
    if (direction != cs2::Direction::Forward && direction != cs2::Direction::Backward)
        return false; // "keep"
    // A query's answer repeats the direction; only a change (or a direction set by us, see
    // directionSet) means that the station stopped the locomotive.
    const bool turned = directionConfirmed_ && direction != direction_;
    const bool changed = direction != direction_ || (turned && speed_ != 0) || !directionConfirmed_;
    directionConfirmed_ = true;
    direction_ = direction;
    if (turned)
        speed_ = 0;
    return changed;
}

bool Locomotive::directionSet(cs2::Direction direction) {
    const bool changed = confirmDirection(direction) || speed_ != 0;
    speed_ = 0;
    speedConfirmed_ = true;
    return changed;
}

bool Locomotive::confirmFunction(int number, bool on) {
    if (number < 0 || number >= MaxFunctions)
        return false;
    auto it = std::ranges::find(functions_, number, &LocomotiveFunction::number);
    if (it == functions_.end()) {
        // A function the file does not list (another controller switched it): keep it anyway.
        it = functions_.insert(std::ranges::upper_bound(functions_, number, {}, &LocomotiveFunction::number),
                               LocomotiveFunction{number, 0, cs2config::FunctionTrigger::Latching, false, 0});
    }
    const bool newlyReported = (functionsConfirmed_ >> number & 1U) == 0;
    functionsConfirmed_ |= 1U << number;
    if (it->on == on)
        return newlyReported;
    it->on = on;
    return true;
}

void Locomotive::keepConfirmedState(const Locomotive& seen) {
    if (seen.speedConfirmed_)
        speed_ = seen.speed_;
    if (seen.directionConfirmed_)
        direction_ = seen.direction_;
    speedConfirmed_ |= seen.speedConfirmed_;
    directionConfirmed_ |= seen.directionConfirmed_;
    for (const LocomotiveFunction& f : seen.functions_)
        if (seen.functionsConfirmed_ >> f.number & 1U)
            confirmFunction(f.number, f.on);
}

} // namespace stellwerk::model
