#pragma once

#include "cs2/Codec.h"
#include "cs2/Header.h"
#include "cs2/Messages.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace stellwerk::sim {

// Track power as the station's STOP/GO/HALT keys set it.
enum class TrackPower { Stopped, Running, Halted };

// What the simulated station knows about one locomotive decoder (by Loc-ID).
struct SimulatedLoco {
    std::uint32_t locId = 0;
    bool inCycle = false;                      // in the refresh cycle (speed/direction/functions known)
    std::uint16_t speed = 0;                   // system speed 0..1000 (1023 at most)
    std::uint8_t direction = 1;                // 1 forward, 2 backward (document 3.5)
    std::array<std::uint8_t, 32> functions{};  // F0..F31: 0 off, 1 on (the station keeps no dim value)
    std::uint8_t trackProtocol = 0;            // sub-protocol of 2.6
    std::map<std::uint16_t, std::uint8_t> cvs; // CV store by packed CV index/number (cs2::CvAddress)
};

// A feedback contact as the station last saw it.
struct ContactState {
    bool occupied = false;
    std::chrono::steady_clock::time_point changedAt{};
};

// Everything the station remembers between frames; the command handlers share it.
struct StationState {
    TrackPower power = TrackPower::Stopped;
    std::map<std::uint32_t, SimulatedLoco> locos;      // by Loc-ID
    std::map<std::uint32_t, std::uint8_t> accessories; // position by Loc-ID
    std::map<std::uint32_t, ContactState> contacts;    // by device << 16 | contact
    std::uint8_t trackProtocols = 0x07;                // 2.9: MM2 | mfx | DCC after reset
    std::uint16_t switchTime10ms = 0;                  // 2.7: 0 = default
    std::uint16_t mfxRegistrationCounter = 1;          // 2.10
    std::uint16_t deviceId = 1;                        // 2.13 feedback/automation device id

    SimulatedLoco& loco(std::uint32_t locId);
    const SimulatedLoco* findLoco(std::uint32_t locId) const;
};

// Who the station is on the bus: the UIDs it answers to and the hash it sends with.
struct StationIdentity {
    std::uint32_t uid = 0;
    std::optional<std::uint32_t> gleisboxUid;
    std::uint16_t hash = 0;
    // What it answers a ping as: a Central Station GUI (0xFFFF), the MS1s' M-CAN master; or, told not to be
    // their master, a Gleisbox (0x0010), which is none.
    std::uint16_t deviceType = 0xFFFF;

    // The target of a system command means us: everybody (0), the station or its Gleisbox.
    bool addressedBy(std::uint32_t target) const {
        return target == 0 || target == uid || (gleisboxUid && target == *gleisboxUid);
    }
    bool isOurDevice(std::uint32_t device) const {
        return device == uid || (gleisboxUid && device == *gleisboxUid);
    }
};

// The frames of one answer, collected so that they go out in one emission.
class Outbox {
public:
    explicit Outbox(std::uint16_t hash) : hash_(hash) {}

    // A response (response bit set) with the station's hash.
    void respond(const cs2::MessageBody& body, std::uint8_t prio = 0) {
        frames_.push_back(cs2::encode(cs2::Message{prio, true, hash_, body}));
    }
    void add(const can::CanFrame& frame) { frames_.push_back(frame); }
    void add(const std::vector<can::CanFrame>& frames) {
        frames_.insert(frames_.end(), frames.begin(), frames.end());
    }

    std::uint16_t hash() const { return hash_; }
    const std::vector<can::CanFrame>& frames() const { return frames_; }
    std::vector<can::CanFrame> take() { return std::move(frames_); }

private:
    std::uint16_t hash_;
    std::vector<can::CanFrame> frames_;
};

} // namespace stellwerk::sim
