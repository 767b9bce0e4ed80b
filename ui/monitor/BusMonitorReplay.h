#pragma once

#include "can/CanFrame.h"
#include "monitor/BusMonitorLog.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <optional>
#include <vector>

class QTimer;

namespace stellwerk::ui {

// Plays a candump log back with its original timing (or faster), a few frames per turn of the event
// loop, so that a recorded session can be watched again without blocking the window.
class BusMonitorReplay final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(BusMonitorReplay)

public:
    enum class State { Idle, Playing, Paused, Finished };
    Q_ENUM(State)

    // The speed factor that plays without waiting between frames.
    static constexpr double AsFastAsPossible = 0.0;
    // At most this many lines are read per turn of the event loop.
    static constexpr int LinesPerTurn = 2000;

    explicit BusMonitorReplay(QObject* parent = nullptr);
    ~BusMonitorReplay() override;

    // Starts playing the log at `path` from its first frame (ending the one that played); returns an
    // error text, empty on success, and then changes nothing.
    QString start(const QString& path);
    // 1 = original timing, 2 = twice as fast, ...; AsFastAsPossible = no waiting. Applies at once.
    void setSpeed(double factor);
    double speed() const { return m_speed; }
    void pause();
    void resume();
    // Ends the replay; nothing more is delivered.
    void stop();

    State state() const { return m_state; }
    QString fileName() const { return m_reader.fileName(); }
    // Share of the file played, 0..100.
    int percent() const;
    qsizetype framesPlayed() const { return m_played; }
    qsizetype linesSkipped() const { return m_skipped; }

signals:
    // Frames of the log that are due now, all stamped `time` in the log (a line without a stamp has the
    // time of the stamped line before it, or now when there is none), all sent (`outgoing`) or not, all
    // on one bus.
    void framesReplayed(const std::vector<stellwerk::can::CanFrame>& frames, const QDateTime& time,
                        bool outgoing, int bus);
    // A line that held no frame was skipped; `reason` says why.
    void lineSkipped(int line, const QString& reason);
    void progressChanged(int percent);
    void stateChanged(stellwerk::ui::BusMonitorReplay::State state);

private:
    void setState(State state);
    void playDue();
    bool readPending();
    qint64 logNowUs() const;
    void rebase();
    void scheduleNext();
    void reportProgress();

    BusMonitorLogReader m_reader;
    QTimer* m_timer = nullptr;
    State m_state = State::Idle;
    double m_speed = 1.0;
    std::optional<BusMonitorLogLine> m_pending; // the next frame, read but not yet due
    qint64 m_pendingEnd = 0;                    // where in the file the pending frame's line ends
    qint64 m_playedEnd = 0;                     // where the last played line ends
    qint64 m_lastLogUs = 0;                     // the time of the last stamped line
    bool m_haveLogTime = false;
    qint64 m_anchorLogUs = 0; // log time when m_clock was last started
    QElapsedTimer m_clock;
    qsizetype m_played = 0;
    qsizetype m_skipped = 0;
    int m_percent = 0;
};

} // namespace stellwerk::ui
