#include "model/RailwayThrottles.h"

#include "model/Railway.h"
#include "orccentral/OrcSession.h"

namespace stellwerk::model {

RailwayThrottles::RailwayThrottles(Railway& railway, QObject* parent) : QObject(parent), railway_(railway) {}

RailwayThrottles::~RailwayThrottles() {
    delete bridge_.data();
}

void RailwayThrottles::setSession(orccentral::OrcSession* orc) {
    if (bridge_ && bridge_->parent() == orc)
        return;
    delete bridge_.data();
    if (orc)
        bridge_ = new orccentral::ThrottleBridge(orc->bus(), *this, orc->busId(), orc);
}

// Reported only as far as the station confirmed it: speed and direction, and functions not reported count as
// off.
std::optional<orccentral::LocoState> RailwayThrottles::loco(std::uint32_t locId) const {
    const Locomotive* found = railway_.locomotive(locId);
    if (!found || !railway_.isStateReported() || !found->isSpeedReported() || !found->isDirectionReported())
        return std::nullopt;
    orccentral::LocoState state{found->speed(), found->direction() != cs2::Direction::Backward, 0};
    for (int number = 0; number < Locomotive::MaxFunctions; ++number)
        if (found->isFunctionReported(number) && found->functionOn(number))
            state.functions |= 1u << number;
    return state;
}

void RailwayThrottles::setSpeed(std::uint32_t locId, int speed) {
    railway_.setSpeed(locId, speed);
}

void RailwayThrottles::setDirection(std::uint32_t locId, bool forward) {
    railway_.setDirection(locId, forward ? cs2::Direction::Forward : cs2::Direction::Backward);
}

void RailwayThrottles::setFunction(std::uint32_t locId, int function, bool on) {
    railway_.setFunction(locId, function, on);
}

void RailwayThrottles::emergencyStop(std::uint32_t locId) {
    railway_.emergencyStop(locId);
}

void RailwayThrottles::stopAll() {
    railway_.stop();
}

} // namespace stellwerk::model
