#pragma once

#include <QPointer>
#include <QStringList>
#include <QWidget>
#include <memory>
#include <vector>

class QComboBox;
class QDateTime;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableView;

namespace stellwerk::can {
struct CanFrame;
}
namespace stellwerk::connection {
class ConnectionBuses;
}

namespace stellwerk::ui {

class BusMonitorFilter;
class BusMonitorFilterBar;
class BusMonitorLogWriter;
class BusMonitorModel;
class BusMonitorReplay;
class BusMonitorTable;

// A workspace tab that shows every frame on the connection's buses as it passes, both ways, decoded by
// the core, so that a user can see what the app, the station and other controllers say without a CAN
// adapter. With more than one bus, a column says which bus a frame was on.
class BusMonitorPanel final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(BusMonitorPanel)

public:
    explicit BusMonitorPanel(QWidget* parent = nullptr);
    ~BusMonitorPanel() override;

    // Shows the frames on the connection's `buses` (received and sent) from now on (null: none). They
    // must outlive the panel or be replaced before they go.
    void setBuses(connection::ConnectionBuses* buses);

    BusMonitorModel* model() const { return m_model; }
    BusMonitorFilter* filter() const { return m_filter; }
    BusMonitorReplay* replay() const { return m_replay; }
    QTableView* table() const;
    // Shows only frames of the protocol named ("cs2", "mcan", "foreign"); empty = all. Returns false for a
    // name the list does not hold.
    bool setProtocolFilter(const QString& name);
    // Shows only rows whose message, details or frame contain `text` (case-insensitive); applied at once.
    void setFilterText(const QString& text);
    // Shows only rows of the command `name` ("loco.speed"); empty = all. Returns false for a name the
    // list does not hold.
    bool setCommandFilter(const QString& name);
    // Shows only rows addressing the Loc-ID written in `text` ("0xC003", "dcc 3"); empty = all. Returns
    // false (and filters nothing by Loc-ID) when the text is not a Loc-ID.
    bool setLocIdFilter(const QString& text);
    // Shows only the M-CAN frames of one MS1 handheld: a node of its pair ("43", "42") or the name it sent;
    // empty = all. Returns false (and filters nothing by handheld) when the text names no handheld.
    bool setHandheldFilter(const QString& text);
    // Writes every frame seen from now on to a candump log at `path`; returns an error text, empty on
    // success. stopRecording() closes the file.
    QString startRecording(const QString& path);
    void stopRecording();
    bool isRecording() const;
    // Clears the table and plays the frames of a candump log into it with their original timing (at the
    // chosen speed) instead of the live ones; returns an error text, empty on success. backToLive() ends it.
    QString openLog(const QString& path);
    // 1, 2, 10 or BusMonitorReplay::AsFastAsPossible.
    void setReplaySpeed(double factor);
    void backToLive();

protected:
    void changeEvent(QEvent* event) override;

private:
    QLayout* createFilterBar();
    QLayout* createFileBar();
    QWidget* createReplayBar();
    void receive(int bus, const std::vector<can::CanFrame>& frames, bool outgoing);
    void replayed(const std::vector<can::CanFrame>& frames, const QDateTime& time, bool outgoing, int bus);
    void takeBuses();
    void showBusColumn();
    void lineSkipped(int line, const QString& reason);
    void replayStateChanged();
    void chooseRecording(bool start);
    void chooseLog();
    void updateCounter();
    void updateReplayStatus();
    void retranslate();
    void retranslateReplay();

    BusMonitorModel* m_model = nullptr;
    BusMonitorFilter* m_filter = nullptr;
    BusMonitorReplay* m_replay = nullptr;
    BusMonitorTable* m_table = nullptr;
    BusMonitorFilterBar* m_filterBar = nullptr;
    QPushButton* m_pauseButton = nullptr;
    QPushButton* m_clearButton = nullptr;
    QPushButton* m_recordButton = nullptr;
    QPushButton* m_openButton = nullptr;
    QLabel* m_historyLabel = nullptr;
    QSpinBox* m_history = nullptr;
    QLabel* m_counter = nullptr;
    QWidget* m_replayBar = nullptr;
    QLabel* m_replayTitle = nullptr;
    QComboBox* m_speedBox = nullptr;
    QPushButton* m_replayPauseButton = nullptr;
    QPushButton* m_liveButton = nullptr;
    QProgressBar* m_replayProgress = nullptr;
    QLabel* m_replayStatus = nullptr;
    QPointer<connection::ConnectionBuses> m_buses;
    std::unique_ptr<BusMonitorLogWriter> m_recorder;
    QStringList m_skippedLines; // "line 3: why", the first MaxSkippedShown of them
};

} // namespace stellwerk::ui
