#pragma once

#include "cs2/Messages.h"

#include <QObject>
#include <chrono>
#include <cstdint>
#include <functional>
#include <unordered_map>

class QTimer;

namespace stellwerk::station {

// When to ping and when silence means trouble.
struct LivenessSettings {
    std::chrono::milliseconds interval{1000};
    int missedPings = 3; // silent after this many intervals without an answer
};

// Pings the bus periodically (0x18, DLC 0) and watches the answers: the station (any answering device)
// and each device that answered once are reported silent when they stop answering, and recovered when
// they answer again.
class Liveness final : public QObject {
    Q_OBJECT

public:
    using PingSender = std::function<void()>;

    explicit Liveness(PingSender sendPing, QObject* parent = nullptr);

    void setSettings(LivenessSettings settings);
    const LivenessSettings& settings() const { return settings_; }

    void start();
    void stop();
    bool running() const;

    // A ping answer arrived.
    void answered(const cs2::DeviceIdentity& device);

    bool isStationSilent() const { return stationSilent_; }
    bool isSilent(std::uint32_t uid) const;

signals:
    void stationSilent();
    void stationRecovered();
    void deviceSilent(std::uint32_t uid);
    void deviceRecovered(std::uint32_t uid);

private:
    using Clock = std::chrono::steady_clock;

    struct Watch {
        Clock::time_point lastAnswer;
        bool silent = false;
    };

    void tick();
    std::chrono::milliseconds silentAfter() const { return settings_.interval * settings_.missedPings; }

    PingSender sendPing_;
    LivenessSettings settings_;
    QTimer* timer_;
    Clock::time_point lastAnswer_;
    bool stationSilent_ = false;
    std::unordered_map<std::uint32_t, Watch> devices_;
};

} // namespace stellwerk::station
