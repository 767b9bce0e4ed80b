#pragma once

#include "base/Expected.h"
#include "cs2config/ConfigStreamReceiver.h"
#include "cs2config/ConfigStreamRequest.h"
#include "station/CommandTracker.h"

#include <QObject>
#include <QString>
#include <chrono>
#include <deque>
#include <functional>
#include <optional>
#include <span>

class QTimer;

namespace stellwerk::station {

using DownloadResult = Expected<cs2config::ReceivedConfigFile, QString>;

// Fetches configuration files from the station one at a time (document 7.1/7.2): sends the request,
// waits for its acknowledgement (sent again when missing) and collects the 0x21 stream addressed to our
// hash. A stream that stops for longer than the idle time is reported, never waited for forever.
class ConfigDownload final : public QObject {
    Q_OBJECT

public:
    using Done = std::function<void(const DownloadResult&)>;
    using HashSource = std::function<std::uint16_t()>;

    ConfigDownload(CommandTracker& tracker, HashSource ownHash, QObject* parent = nullptr);

    void setRequestPolicy(CommandPolicy policy) { policy_ = policy; }
    // How long a stream may pause (or take to begin after the acknowledgement).
    void setIdleTimeout(std::chrono::milliseconds timeout) { idle_ = timeout; }

    // Queues a request; `done` gets the file or a sentence saying what went wrong.
    void fetch(cs2config::ConfigRequest request, Done done);
    // A received 0x21 frame (any hash; frames of other requesters are ignored).
    void feed(const can::CanFrame& frame);
    // Called once per received batch: reports progress if it changed.
    void flushProgress();

    bool busy() const { return active_.has_value(); }

signals:
    // Bytes of the current file received so far and the length its header announced.
    void progress(const QString& key, qsizetype received, qsizetype announced);

private:
    struct Job {
        cs2config::ConfigRequest request;
        Done done;
        CommandId command = 0;
        std::uint16_t hash = 0;
        bool acknowledged = false;
    };

    void startNext();
    void requestAnswered(const CommandResult& result);
    void idleExpired();
    void complete(const DownloadResult& result);
    bool isOurs(const can::CanFrame& frame) const;

    CommandTracker& tracker_;
    HashSource ownHash_;
    CommandPolicy policy_{};
    std::chrono::milliseconds idle_{2000};
    QTimer* idleTimer_;
    cs2config::ConfigStreamReceiver receiver_;
    std::deque<Job> queue_;
    std::optional<Job> active_;
    cs2config::StreamProgress lastReported_;
    bool progressDirty_ = false;
};

} // namespace stellwerk::station
