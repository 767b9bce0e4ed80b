#pragma once

#include "sim/StationState.h"
#include "sim/StatusChannels.h"

#include <optional>

namespace stellwerk::sim {

// Chapter 6 and system status (2.12): answers ping as the CS2 master (and as a Gleisbox when the
// station has one), serves status data configuration (6.2) framed as real devices do, reads the
// measurement channels from the track load, takes configuration writes, and reports an overload
// (2.11) and stops the track when the current passes the limit.
class DeviceService {
public:
    static constexpr std::uint16_t MasterType = 0xFFFF;   // CS2 GUI (master)
    static constexpr std::uint16_t GleisboxType = 0x0010; // Gleisbox 60112/60113
    static constexpr std::uint8_t VersionMajor = 4, VersionMinor = 2;

    DeviceService(StationState& state, const StationIdentity& identity);

    bool handle(const cs2::Message& message, Outbox& out);

    void setTrackLoad(int milliampere) { loadMa_ = milliampere < 0 ? 0 : milliampere; }
    // Reports an overload when the powered track draws more than the limit, and stops the track.
    void watchLoad(Outbox& out);
    // The main-track current flowing now (none while the track is off).
    double mainTrackAmpere() const;
    const StatusChannels& stationChannels() const { return station_; }

private:
    void ping(const cs2::Ping& request, const cs2::Message& message, Outbox& out);
    void describe(const cs2::StatusDataConfig& request, const cs2::Message& message, Outbox& out);
    void status(const cs2::SystemStatus& request, const cs2::Message& message, Outbox& out);
    StatusChannels* channelsOf(std::uint32_t device);

    StationState& state_;
    const StationIdentity& identity_;
    StatusChannels station_;
    std::optional<StatusChannels> gleisbox_;
    int loadMa_ = 0;
};

} // namespace stellwerk::sim
