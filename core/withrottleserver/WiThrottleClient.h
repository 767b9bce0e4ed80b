#pragma once

#include "model/ThrottlePort.h"
#include "withrottle/LineSplitter.h"

#include <QDateTime>
#include <QPointer>
#include <QString>
#include <QTcpSocket>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::withrottleserver {

// A locomotive in one of a client's throttles, under the key the client chose, with what the client was
// last told of it (so that only changes are sent).
struct ThrottleLoco {
    std::uint32_t locId = 0;
    std::string key;
    std::optional<model::LocoRun> told;
};

// One WiThrottle client (a TCP connection): its device name and id, its throttles (T, S, 0-5...) with the
// locomotives they hold, whether its heartbeat is watched, when it was last heard, and what it sent that
// was wrong or too much.
struct WiThrottleClient {
    QPointer<QTcpSocket> socket;
    QString peer; // "127.0.0.1:51234"
    std::string deviceName;
    std::string hardwareId;
    std::map<char, std::vector<ThrottleLoco>> throttles;
    bool heartbeatWatched = true;
    bool gone = false; // stopped and closed; taken out of the book once nothing uses it
    qint64 lastHeardMs = 0;
    QDateTime lastLineAt;     // wall-clock time of the last line read, for the Throttles panel
    QString lastLine;         // that line as it came, cut to 60 characters
    qint64 windowStartMs = 0; // the flood limit's one-second window
    int linesInWindow = 0;
    std::uint64_t lines = 0;
    std::uint64_t unknownLines = 0;
    std::uint64_t limited = 0;
    withrottle::LineSplitter splitter;

    // The throttle name the owner book knows it by: "withrottle 127.0.0.1:51234".
    QString name() const;
    // The locomotives of throttle `throttle` under `key` ("*": all of them).
    std::vector<ThrottleLoco*> locos(char throttle, const std::string& key);
    ThrottleLoco* holding(char throttle, std::uint32_t locId);
    // Every (throttle, locomotive) that holds the loco.
    std::vector<std::pair<char, ThrottleLoco*>> holdersOf(std::uint32_t locId);
    // Takes the loco out of every throttle; the throttles and keys it was held under are returned.
    std::vector<std::pair<char, std::string>> forget(std::uint32_t locId);
    // Whether one more line is within `perSecond`; the others are counted and dropped.
    bool admit(qint64 nowMs, int perSecond);
};

} // namespace stellwerk::withrottleserver
