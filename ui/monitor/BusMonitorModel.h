#pragma once

#include "can/CanFrame.h"
#include "monitor/FrameDescriptions.h"

#include <QAbstractTableModel>
#include <QDateTime>
#include <QString>
#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

class QTimer;

namespace stellwerk::ui {

// A bus the monitor's rows may come from: its name for the bus column and the protocols expected on it.
struct MonitoredBus {
    QString name;
    busreading::BusProfile profile;
};

// The bus monitor's rows: a bounded history of compact frame records (no text per frame; the core's
// FrameDescription, cached for the rows looked at, writes the text when a row is shown), filled in
// batches so that a flood of frames costs one insert per flush instead of one per frame. Each row knows
// the bus it came from; the bus column says which when there is more than one. Each bus has a context that
// learns, from every frame in the order it arrived, what one frame does not say (an MS1's handles and
// names); a row is described with what its bus has revealed so far.
class BusMonitorModel final : public QAbstractTableModel {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(BusMonitorModel)

public:
    enum Column {
        TimeColumn,
        BusColumn,
        DirectionColumn,
        MessageColumn,
        DetailsColumn,
        FrameColumn,
        ColumnCount
    };
    enum class Direction : std::uint8_t { Received, Sent };
    // What kind of command a row carries; each has its own colour.
    enum class Group : std::uint8_t { System, Loco, Accessory, Feedback, Stream, Handheld, Other };
    enum Role {
        // name, details and frame text in one string (decodes the frame once); BusMonitorFilter uses the
        // cheaper containsText()
        SearchTextRole = Qt::UserRole + 1,
        GroupRole,    // the row's Group as int
        CommandRole,  // the command's vocabulary name ("loco.speed"), also for frames that did not decode
        LocIdRole,    // the Loc-ID the frame addresses as uint, or invalid when it names none
        ProtocolRole, // the protocol's short name ("cs2", "foreign")
    };

    static constexpr int DefaultHistory = 100000;
    static constexpr int FlushIntervalMs = 50;

    explicit BusMonitorModel(QObject* parent = nullptr);

    // Queues frames seen now; they appear at the next flush (at most FlushIntervalMs later).
    void addFrames(std::span<const can::CanFrame> frames, Direction direction);
    void addFrames(std::span<const can::CanFrame> frames, Direction direction, const QDateTime& time,
                   int bus = 0);
    // The connection's buses, by number (0: the station's). A row of a bus not named here (bus 3 of a
    // replayed log) is called "can3" and read with no protocol expected (bus 0: the CS2's).
    void setBuses(std::vector<MonitoredBus> buses);
    // The buses named or seen in a row since the last clear(), whichever are more.
    int busCount() const { return m_busCount; }
    QString busName(int bus) const;
    // Moves the queued frames into the table now: one row insertion (and at most one removal of the
    // oldest rows) per call. Nothing moves while paused.
    void flush();

    // How many rows are kept; older ones go when newer ones come. Shrinking drops the oldest at once.
    void setHistoryLimit(int rows);
    int historyLimit() const { return m_historyLimit; }

    // While paused, frames are counted and held back (up to the history limit), and shown on resume.
    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }
    // Frames that arrived since the pause began.
    std::uint64_t heldBack() const { return m_heldBack; }
    // Every frame ever given to addFrames() since the last clear().
    std::uint64_t totalFrames() const { return m_total; }
    // Forgets all rows, queued frames and counters; what the buses revealed stays (the buses go on).
    void clear();
    // Forgets what the buses revealed (an MS1's handles and names): for a log shown instead of the live
    // buses, and back.
    void forgetBusContexts();

    can::CanFrame frameAt(int row) const;
    QDateTime timeAt(int row) const;
    Direction directionAt(int row) const;
    // "← received" or "→ sent", as the Direction column shows it.
    static QString directionText(Direction direction);
    int busAt(int row) const;
    // The protocol the frame of `row` belongs to on its bus.
    busreading::Protocol protocolAt(int row) const;
    // The Loc-ID field of the frame in `row`, read by the core's decoder; nullopt when it has none.
    std::optional<std::uint32_t> locIdAt(int row) const;
    // The MS1 handheld whose frame `row` is (M-CAN), with the name its bus knows for it now.
    std::optional<busreading::Handheld> handheldAt(int row) const;
    // The command's vocabulary name ("loco.speed"), also for a frame that did not decode.
    std::string commandAt(int row) const;
    // How many frames were decoded so far: each shown or filtered row once while it is in the cache.
    std::uint64_t decodeCount() const { return m_descriptions.decodeCount(); }
    // Whether the message name, details or frame text of `row` contain `lowerNeedle` (ASCII, lower case),
    // ignoring case; cheaper than SearchTextRole for scanning many rows.
    bool containsText(int row, std::string_view lowerNeedle) const;
    // How many rows went from the front since the last clear(). Row r has the number firstSequence() + r,
    // which it keeps while older rows go.
    std::uint64_t firstSequence() const { return m_dropped; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

signals:
    // After each flush that changed something, and after pause, resume and clear (for counters).
    void countsChanged();
    // The bus column matters (more than one bus) or stopped mattering.
    void busCountChanged(int count);

private:
    // 24 bytes per frame: a million rows fit in about 24 MB.
    struct Record {
        qint64 timeMs;
        std::uint32_t id;
        std::uint8_t dlc;
        Direction direction;
        bool extended;
        std::uint8_t bus;
        std::array<std::uint8_t, 8> data;
    };

    static Record record(const can::CanFrame& frame, Direction direction, qint64 timeMs, int bus);
    const busreading::BusProfile& profileOf(int bus) const;
    busreading::BusContext& contextOf(int bus);
    void noteBus(int bus);
    void dropOldest(std::size_t count);
    QVariant display(const busreading::FrameDescription& description, const Record& record, int column) const;
    const busreading::FrameDescription& describe(int row) const;

    std::deque<Record> m_rows;
    std::deque<Record> m_queued;
    QTimer* m_flushTimer = nullptr;
    int m_historyLimit = DefaultHistory;
    bool m_paused = false;
    std::uint64_t m_heldBack = 0;
    std::uint64_t m_total = 0;
    std::uint64_t m_dropped = 0;
    FrameDescriptions m_descriptions;
    std::vector<MonitoredBus> m_buses;
    std::vector<busreading::BusContext> m_contexts; // by bus number, as far as frames came
    int m_busCount = 1;
};

} // namespace stellwerk::ui
