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

// Reported only as far as the station confirmed it (the throttle port's confirmed state).
std::optional<orccentral::LocoState> RailwayThrottles::loco(std::uint32_t locId) const {
    const std::optional<LocoRun> run = railway_.throttlePort().confirmed(locId);
    if (!run)
        return std::nullopt;
    return orccentral::LocoState{run->speed, run->forward, run->functions};
}

void RailwayThrottles::setSpeed(std::uint32_t locId, int speed) {
    railway_.throttlePort().setSpeed(ThrottlePort::orcThrottles(), locId, speed);
}

void RailwayThrottles::setDirection(std::uint32_t locId, bool forward) {
    railway_.throttlePort().setDirection(ThrottlePort::orcThrottles(), locId, forward);
}

void RailwayThrottles::setFunction(std::uint32_t locId, int function, bool on) {
    railway_.throttlePort().setFunction(ThrottlePort::orcThrottles(), locId, function, on);
}

void RailwayThrottles::emergencyStop(std::uint32_t locId) {
    railway_.throttlePort().emergencyStop(ThrottlePort::orcThrottles(), locId);
}

void RailwayThrottles::stopAll() {
    railway_.throttlePort().setPower(false);
}

} // namespace stellwerk::model
