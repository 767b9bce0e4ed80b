#pragma once

#include "cs2/Messages.h"
#include "station/CommandTracker.h"
#include "station/DeviceDescription.h"
#include "station/StatusDataPackets.h"

#include <QObject>
#include <QStringList>
#include <deque>
#include <functional>
#include <vector>

namespace stellwerk::station {

// Reads a device's status-data configuration (command 0x1D, document 6.2): index 0, then every reading
// and config channel it announces, one index at a time (the document allows one request in flight).
// Reassembles the data packets (hash 0x0301, 0x0302, ...) that precede each end frame.
class StatusDataReader final : public QObject {
    Q_OBJECT

public:
    using Done = std::function<void(const DeviceDescription& device, const QStringList& problems)>;

    explicit StatusDataReader(CommandTracker& tracker, QObject* parent = nullptr);

    void setPolicy(CommandPolicy policy) { policy_ = policy; }
    // Queues the device; `done` gets what could be read and a sentence for every index that could not.
    void read(const cs2::DeviceIdentity& device, Done done);
    // A status-data packet (response, DLC 8, hash = packet number).
    void feedPacket(const cs2::StatusDataConfig& packet, std::uint16_t hash);

    bool busy() const { return active_.has_value(); }

private:
    struct Job {
        DeviceDescription device;
        Done done;
        QStringList problems;
        std::uint8_t index = 0;
    };

    void startNext();
    void requestIndex();
    void indexAnswered(const CommandResult& result);
    void store(std::span<const std::uint8_t> bytes);
    void finishJob();

    CommandTracker& tracker_;
    CommandPolicy policy_{std::chrono::milliseconds(1000), 1, false};
    std::deque<Job> queue_;
    std::optional<Job> active_;
    StatusDataPackets packets_;
};

} // namespace stellwerk::station
