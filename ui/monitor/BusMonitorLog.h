#pragma once

#include "can/CanFrame.h"

#include <QDateTime>
#include <QFile>
#include <QString>
#include <optional>
#include <span>

namespace stellwerk::ui {

// Keeps what the bus monitor saw in a candump log file ("(1700000000.123000) can0 00084711#0000C0030120 T",
// as SocketCAN's candump -l writes and canplayer reads; the R or T after the data marks a received or a
// transmitted frame, and readers that expect three fields skip it), so a session can be shared and
// looked at again. The interface names the bus: can0 for the station's, can1, can2, ... for further ones.
class BusMonitorLogWriter final {
    Q_DISABLE_COPY_MOVE(BusMonitorLogWriter)

public:
    BusMonitorLogWriter() = default;

    // Starts a new file at `path` (replacing one that is there); returns an error text, empty on success.
    QString open(const QString& path);
    void close();
    bool isOpen() const { return m_file.isOpen(); }
    QString fileName() const { return m_file.fileName(); }
    // Appends one line per frame, all with the time `time` and the direction mark, and hands them to the
    // system at once (a crash keeps them); returns false when the disk refused them.
    bool write(std::span<const can::CanFrame> frames, const QDateTime& time, bool outgoing, int bus = 0);

private:
    QFile m_file;
};

// One line of a log that was not blank and not a # comment.
struct BusMonitorLogLine {
    int number = 0;                     // 1-based
    std::optional<can::CanFrame> frame; // empty when the line held no frame
    std::optional<qint64> timeUs;       // the "(seconds.micros)" stamp as microseconds, if the line had one
    bool sent = false;                  // the line ends with the "T" mark (transmitted)
    int bus = 0;                        // N of a "canN" interface name, else 0
    QString problem;                    // why the line held no frame
};

// Reads a candump log one line at a time, so that a large file never has to be read at once. Lines in
// the other notations can::parseFrame reads work too (without a time stamp).
class BusMonitorLogReader final {
    Q_DISABLE_COPY_MOVE(BusMonitorLogReader)

public:
    BusMonitorLogReader() = default;

    // Returns an error text, empty on success.
    QString open(const QString& path);
    QString fileName() const { return m_file.fileName(); }
    // The next line with content; nullopt at the end of the file.
    std::optional<BusMonitorLogLine> next();
    // How far reading has come, in bytes of the file.
    qint64 position() const { return m_file.pos(); }
    qint64 size() const { return m_file.size(); }

private:
    QFile m_file;
    int m_number = 0;
};

} // namespace stellwerk::ui
