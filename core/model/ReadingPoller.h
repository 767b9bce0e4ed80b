#pragma once

#include "station/CommandTracker.h"

#include <QObject>
#include <chrono>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

class QTimer;

namespace stellwerk::station {
class StationSession;
}

namespace stellwerk::model {

// A measurement channel of a device, as system status 0x0B asks for it.
struct ReadingSource {
    std::uint32_t device = 0;
    std::uint8_t channel = 0;

    friend auto operator<=>(const ReadingSource&, const ReadingSource&) = default;
};

// Asks the devices for their readings on a timer (gauges need about one value a second, never one per
// frame): one system status 0x0B request per channel and tick, and none for a channel whose last
// request is still unanswered. The values arrive as StationUpdates; a request without answer is
// reported so that the gauge can show the value as old.
class ReadingPoller final : public QObject {
    Q_OBJECT

public:
    explicit ReadingPoller(station::StationSession& session, QObject* parent = nullptr);
    ~ReadingPoller() override;

    void setSources(std::vector<ReadingSource> sources);
    const std::vector<ReadingSource>& sources() const { return sources_; }
    void setInterval(std::chrono::milliseconds interval);
    std::chrono::milliseconds interval() const;

    void start();
    void stop();
    bool running() const;
    // Pauses a started poller while nobody looks at the readings (a hidden gauge page) and resumes it;
    // start() while inactive only takes note. Active from construction.
    void setActive(bool active);
    bool active() const { return active_; }
    // One round of requests now.
    void poll();

signals:
    void readingMissed(quint32 device, quint8 channel);

private:
    void request(ReadingSource source);

    station::StationSession& session_;
    QTimer* timer_;
    std::vector<ReadingSource> sources_;
    std::set<ReadingSource> pending_;
    std::vector<station::CommandId> sent_;
    bool started_ = false;
    bool active_ = true;
};

} // namespace stellwerk::model
