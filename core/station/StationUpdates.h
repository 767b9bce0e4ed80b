#pragma once

#include "cs2/LocId.h"
#include "cs2/Messages.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace stellwerk::station {

// A loco's speed as the station confirmed it (0..1000).
struct LocomotiveSpeedChange {
    cs2::LocId loco;
    std::uint16_t speed = 0;
};

// A loco's direction as the station confirmed it; the station also set its speed to 0 (field notes).
struct LocomotiveDirectionChange {
    cs2::LocId loco;
    cs2::Direction direction = cs2::Direction::Forward;
};

struct LocomotiveFunctionChange {
    cs2::LocId loco;
    std::uint8_t function = 0;
    std::uint8_t value = 0;
};

// An accessory output the station switched (position as on the wire; current 0 = output off).
struct AccessoryChange {
    cs2::LocId article;
    std::uint8_t position = 0;
    std::uint8_t current = 0;
};

// An S88 contact's state: the device (feedback device id) and contact number as on the wire.
struct FeedbackContactChange {
    std::uint16_t device = 0;
    std::uint16_t contact = 0;
    bool occupied = false;
    bool wasOccupied = false;
    std::uint16_t time10ms = 0;
};

enum class PowerState : std::uint8_t { Stopped, Running, Halted };

// Track power of one station (target 0 = every station) as confirmed.
struct PowerChange {
    std::uint32_t target = 0;
    PowerState state = PowerState::Stopped;
};

// An overload a station reported on one of its channels.
struct OverloadReport {
    std::uint32_t device = 0;
    std::uint8_t channel = 0;
};

// A measurement a device answered (system status 0x0B, DLC 8 answer).
struct ReadingValue {
    std::uint32_t device = 0;
    std::uint8_t channel = 0;
    std::uint16_t raw = 0;
};

// A state a device announced for one of its automation functions or blocks (9.1, a status answer): the
// value as received (values the document does not define are kept), or the locomotive in the block (DLC 8).
struct AutomationAnnouncement {
    std::uint16_t device = 0;
    std::uint16_t function = 0;
    std::optional<std::uint8_t> state;
    std::optional<cs2::LocId> loco;
};

// Everything one batch of frames changed, from any controller on the bus, so that the model updates
// once per batch. Only confirmed state: answers (response bit) and S88 events.
struct StationUpdates {
    std::vector<LocomotiveSpeedChange> speeds;
    std::vector<LocomotiveDirectionChange> directions;
    std::vector<LocomotiveFunctionChange> functions;
    std::vector<AccessoryChange> accessories;
    std::vector<FeedbackContactChange> contacts;
    std::vector<PowerChange> power;
    std::vector<OverloadReport> overloads;
    std::vector<ReadingValue> readings;
    std::vector<cs2::DeviceIdentity> devices; // ping answers
    std::vector<AutomationAnnouncement> automation;
    // Discovery answers (3.1): steps of an mfx search, a found decoder (range 32), or none (no UID).
    std::vector<cs2::LocoDiscovery> discoveries;
    bool configurationChanged = false; // a broadcast config stream (DLC 7 header) began

    bool empty() const;
    void clear();
};

// Turns received messages into StationUpdates.
class StationEventCollector {
public:
    void observe(const cs2::Message& message);
    bool hasUpdates() const { return !updates_.empty(); }
    const StationUpdates& updates() const { return updates_; }
    void clear() { updates_.clear(); }

private:
    void observeSystem(const cs2::Message& message);

    StationUpdates updates_;
};

} // namespace stellwerk::station
