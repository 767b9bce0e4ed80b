#include "station/Liveness.h"

#include <QTimer>

namespace stellwerk::station {

Liveness::Liveness(PingSender sendPing, QObject* parent)
    : QObject(parent), sendPing_(std::move(sendPing)), timer_(new QTimer(this)) {
    connect(timer_, &QTimer::timeout, this, &Liveness::tick);
}

void Liveness::setSettings(LivenessSettings settings) {
    settings_ = settings;
    if (timer_->isActive())
        timer_->start(settings_.interval);
}

void Liveness::start() {
    lastAnswer_ = Clock::now(); // the first silence is counted from the start
    for (auto& [uid, watch] : devices_)
        watch.lastAnswer = lastAnswer_;
    timer_->start(settings_.interval);
    sendPing_();
}

void Liveness::stop() {
    timer_->stop();
}

bool Liveness::running() const {
    return timer_->isActive();
}

void Liveness::answered(const cs2::DeviceIdentity& device) {
    const auto now = Clock::now();
    lastAnswer_ = now;
    Watch& watch = devices_[device.uid];
    watch.lastAnswer = now;
    if (watch.silent) {
        watch.silent = false;
        emit deviceRecovered(device.uid);
    }
    if (stationSilent_) {
        stationSilent_ = false;
        emit stationRecovered();
    }
}

bool Liveness::isSilent(std::uint32_t uid) const {
    const auto it = devices_.find(uid);
    return it != devices_.end() && it->second.silent;
}

void Liveness::tick() {
    const auto now = Clock::now();
    for (auto& [uid, watch] : devices_) {
        if (!watch.silent && now - watch.lastAnswer >= silentAfter()) {
            watch.silent = true;
            emit deviceSilent(uid);
        }
    }
    if (!stationSilent_ && now - lastAnswer_ >= silentAfter()) {
        stationSilent_ = true;
        emit stationSilent();
    }
    sendPing_();
}

} // namespace stellwerk::station
