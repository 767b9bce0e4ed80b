#pragma once

#include "cs2/CanFrame.h"

#include <QDateTime>
#include <QFile>
#include <QString>
#include <functional>
#include <span>

namespace stellwerk::ui {

// Keeps what the bus monitor saw in a candump log file ("(1700000000.123000) can0 00084711#0000C0030120",
// as SocketCAN's candump -l writes and canplayer reads), so a session can be shared and looked at again.
class BusMonitorLogWriter final {
    Q_DISABLE_COPY_MOVE(BusMonitorLogWriter)

public:
    BusMonitorLogWriter() = default;

    // Starts a new file at `path` (replacing one that is there); returns an error text, empty on success.
    QString open(const QString& path);
    void close();
    bool isOpen() const { return m_file.isOpen(); }
    QString fileName() const { return m_file.fileName(); }
    // Appends one line per frame, all with the time `time`; returns false when the disk refused them.
    bool write(std::span<const cs2::CanFrame> frames, const QDateTime& time);

private:
    QFile m_file;
};

// What reading a candump log found.
struct BusMonitorLogSummary {
    qsizetype frames = 0;
    qsizetype skipped = 0;    // lines that held no frame (other than blank lines and # comments)
    int firstSkippedLine = 0; // 1-based, 0 when none was skipped
    QString error;            // the file could not be read at all
};

// Reads a candump log line by line and hands each frame with its time to `frame` (frames without a
// time get the time of the previous one). Lines in the other notations cs2::parseFrame reads work too.
BusMonitorLogSummary readCandumpLog(const QString& path,
                                    const std::function<void(const cs2::CanFrame&, const QDateTime&)>& frame);

} // namespace stellwerk::ui
