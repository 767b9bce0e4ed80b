#include "model/ThrottlePort.h"

#include "model/Railway.h"

#include <algorithm>

namespace stellwerk::model {

QList<quint32> LocoOwners::drivenBy(const QString& throttle) const {
    QList<quint32> locos;
    for (auto it = drivers_.cbegin(); it != drivers_.cend(); ++it)
        if (it.value() == throttle)
            locos.append(it.key());
    std::sort(locos.begin(), locos.end());
    return locos;
}

QString LocoOwners::take(quint32 loco, const QString& throttle) {
    const QString before = drivers_.value(loco);
    if (before == throttle)
        return {};
    drivers_.insert(loco, throttle);
    if (!before.isEmpty())
        emit takenOver(loco, before, throttle);
    emit driverChanged(loco, throttle);
    return before;
}

void LocoOwners::release(quint32 loco, const QString& throttle) {
    if (drivers_.value(loco) != throttle || throttle.isEmpty())
        return;
    drivers_.remove(loco);
    emit driverChanged(loco, {});
}

QList<quint32> LocoOwners::releaseAll(const QString& throttle) {
    const QList<quint32> locos = drivenBy(throttle);
    for (const quint32 loco : locos)
        release(loco, throttle);
    return locos;
}

ThrottlePort::ThrottlePort(Railway& railway, QObject* parent) : QObject(parent), railway_(railway) {}

std::optional<LocoRun> ThrottlePort::confirmed(quint32 loco) const {
    const Locomotive* found = railway_.locomotive(loco);
    if (!found || !railway_.isStateReported() || !found->isSpeedReported() || !found->isDirectionReported())
        return std::nullopt;
    LocoRun run{found->speed(), found->direction() != cs2::Direction::Backward, 0};
    for (int number = 0; number < Locomotive::MaxFunctions; ++number)
        if (found->isFunctionReported(number) && found->functionOn(number))
            run.functions |= 1u << number;
    return run;
}

std::optional<LocoRun> ThrottlePort::shown(quint32 loco) const {
    const Locomotive* found = railway_.locomotive(loco);
    if (!found)
        return std::nullopt;
    LocoRun run{found->speed(), found->direction() != cs2::Direction::Backward, 0};
    for (int number = 0; number < Locomotive::MaxFunctions; ++number)
        if (found->functionOn(number))
            run.functions |= 1u << number;
    return run;
}

bool ThrottlePort::canDrive() const {
    return railway_.isStateReported();
}

std::optional<bool> ThrottlePort::powerOn() const {
    const std::optional<station::PowerState> power = railway_.power();
    if (!power)
        return std::nullopt;
    return *power != station::PowerState::Stopped;
}

void ThrottlePort::setSpeed(const QString& throttle, quint32 loco, int speed) {
    owners_.take(loco, throttle);
    railway_.setSpeed(loco, speed);
}

void ThrottlePort::setDirection(const QString& throttle, quint32 loco, bool forward) {
    owners_.take(loco, throttle);
    railway_.setDirection(loco, forward ? cs2::Direction::Forward : cs2::Direction::Backward);
}

void ThrottlePort::setFunction(const QString& throttle, quint32 loco, int function, bool on) {
    owners_.take(loco, throttle);
    railway_.setFunction(loco, function, on);
}

void ThrottlePort::emergencyStop(const QString& throttle, quint32 loco) {
    owners_.take(loco, throttle);
    railway_.emergencyStop(loco);
}

void ThrottlePort::setPower(bool on) {
    if (on)
        railway_.go();
    else
        railway_.stop();
}

QList<quint32> ThrottlePort::stopDrivenBy(const QString& throttle) {
    const QList<quint32> locos = owners_.releaseAll(throttle);
    for (const quint32 loco : locos)
        railway_.setSpeed(loco, 0);
    return locos;
}

} // namespace stellwerk::model
