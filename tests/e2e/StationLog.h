#pragma once

#include "cs2/Codec.h"
#include "cs2/Messages.h"
#include "sim/SimulatedStation.h"

#include <QObject>
#include <cstdint>
#include <optional>
#include <vector>

namespace stellwerk::e2e {

// What reached the simulated station (its received log), to assert that nothing given up ever arrives.
class StationLog {
public:
    explicit StationLog(sim::SimulatedStation& station) {
        QObject::connect(&station, &sim::SimulatedStation::frameReceived, &context_,
                         [this](const can::CanFrame& frame) { frames_.push_back(frame); });
    }

    const std::vector<can::CanFrame>& frames() const { return frames_; }
    void clear() { frames_.clear(); }

    // Every speed command (not a query) for the loco that reached the station, in order.
    std::vector<std::uint16_t> speedsSet(std::uint32_t locId) const {
        std::vector<std::uint16_t> speeds;
        for (const can::CanFrame& frame : frames_) {
            const auto message = cs2::decode(frame);
            const auto* speed = message ? std::get_if<cs2::LocoSpeed>(&message->body) : nullptr;
            if (speed && !message->response && speed->loco.value() == locId && speed->speed)
                speeds.push_back(*speed->speed);
        }
        return speeds;
    }

    bool received(std::uint32_t locId, std::uint16_t speed) const {
        for (const std::uint16_t value : speedsSet(locId))
            if (value == speed)
                return true;
        return false;
    }

private:
    QObject context_;
    std::vector<can::CanFrame> frames_;
};

} // namespace stellwerk::e2e
