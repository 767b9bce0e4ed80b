#pragma once

#include "bus/Bus.h"
#include "station/CommandTracker.h"
#include "station/ConfigDownload.h"
#include "station/DeviceDirectory.h"
#include "station/Liveness.h"
#include "station/StationIdentity.h"
#include "station/StationUpdates.h"
#include "station/StatusDataReader.h"
#include "transport/Transport.h"

#include <QObject>
#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace stellwerk::station {

// The settings of one station session; the defaults suit a CS2 on a LAN.
struct StationSettings {
    std::optional<std::uint32_t> uid; // random when not given
    CommandPolicy commands{};
    LivenessSettings liveness{};
    std::chrono::milliseconds streamIdle{2000};
};

// What a session has seen since it started, for the status bar and tests.
struct SessionCounters {
    std::uint64_t frames = 0; // CS2 frames; the bus counts those of other protocols
    std::uint64_t undecodable = 0;
    std::uint64_t answersMatched = 0;
    std::uint64_t hashCollisions = 0;
};

// One connected command station: the only place that knows the conversation rules. It subscribes to the
// CS2 frames of its bus (frames of other protocols on a shared bus never reach it) and sends with our
// hash, tracks acknowledgements, watches liveness, downloads files, and turns every frame on the bus
// (ours and other controllers') into batched StationUpdates. When the connection is lost, every command
// still waiting ends at once (Cancelled) and nothing of it is sent when the station is back; when the
// station falls silent, a stream connection is reset so that it cannot read old commands on waking up.
class StationSession final : public QObject {
    Q_OBJECT

public:
    explicit StationSession(bus::Bus& bus, StationSettings settings = {}, QObject* parent = nullptr);
    ~StationSession() override;

    const StationIdentity& identity() const { return identity_; }
    CommandTracker& tracker() { return *tracker_; }
    ConfigDownload& downloads() { return *download_; }
    StatusDataReader& statusData() { return *statusData_; }
    Liveness& liveness() { return *liveness_; }
    DeviceDirectory& devices() { return directory_; }
    const DeviceDirectory& devices() const { return directory_; }
    const SessionCounters& counters() const { return counters_; }
    transport::Transport& transport() { return transport_; }
    bus::Bus& bus() { return bus_; }

    // Sends without waiting for an answer (ping, bootloader "go", commands nobody acknowledges).
    bool send(const cs2::Message& message);
    // Frames as they are, with our hash written in; `ticket` marks them for withdrawing (see Transport).
    bool sendFrames(std::span<const can::CanFrame> frames, transport::SendTicket ticket = 0);
    // Sends and tracks the acknowledgement with the session's default policy (or the given one).
    CommandId request(const cs2::Message& command, CommandCallback done,
                      std::optional<CommandPolicy> policy = std::nullopt);
    void ping();

signals:
    // Everything the last batch of frames changed (never emitted empty).
    void updated(const stellwerk::station::StationUpdates& updates);
    // Another sender used our hash; we now use `newHash`.
    void hashChanged(std::uint16_t oldHash, std::uint16_t newHash);
    // The connection was lost (the transport left Connected). Emitted before the waiting commands are
    // cancelled, so that whoever drives a conversation (the start-up) can abandon it first.
    void connectionLost();
    // The last batch of frames held at least one answer (a frame with the response bit) from a device on
    // the bus: the station is heard. Emitted after updated().
    void answersHeard();

private:
    void transportStateChanged(transport::Transport::State state);
    void stationSilent();
    void commandGivenUp(std::chrono::steady_clock::time_point firstSent);
    void receive(const std::vector<can::CanFrame>& frames);
    void receiveFrame(const can::CanFrame& frame);
    void route(const cs2::Message& message, const can::CanFrame& frame);

    bus::Bus& bus_;
    transport::Transport& transport_;
    StationSettings settings_;
    StationIdentity identity_;
    CommandTracker* tracker_;
    ConfigDownload* download_;
    StatusDataReader* statusData_;
    Liveness* liveness_;
    DeviceDirectory directory_;
    StationEventCollector events_;
    SessionCounters counters_;
    bool connected_ = false;
    bool answerInBatch_ = false;
    std::chrono::steady_clock::time_point lastHeard_; // the last frame received
};

} // namespace stellwerk::station
