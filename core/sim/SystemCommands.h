#pragma once

#include "sim/StationState.h"

namespace stellwerk::sim {

// Chapter 2 (system commands) except the status readings: stop/go/halt, loco emergency stop and
// cycle end, loco protocol, switch time, fast read, track protocols, mfx counter, device id, reset.
// A command addressed to another device gets no answer, as on a real bus.
class SystemCommands {
public:
    SystemCommands(StationState& state, const StationIdentity& identity)
        : state_(state), identity_(identity) {}

    // Handles the message when it is one of these system commands; true when it was.
    bool handle(const cs2::Message& message, Outbox& out);

private:
    void power(std::uint32_t target, TrackPower power, const cs2::Message& message, Outbox& out);
    void emergencyStop(const cs2::LocoEmergencyStop& command, const cs2::Message& message, Outbox& out);
    void cycleEnd(const cs2::LocoCycleEnd& command, const cs2::Message& message, Outbox& out);
    void locoProtocol(const cs2::LocoProtocol& command, const cs2::Message& message, Outbox& out);
    bool settings(const cs2::Message& message, Outbox& out);
    void reset();

    StationState& state_;
    const StationIdentity& identity_;
};

} // namespace stellwerk::sim
