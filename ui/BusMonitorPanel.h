#pragma once

#include <QPointer>
#include <QWidget>
#include <memory>
#include <vector>

class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTableView;
class QTimer;

namespace stellwerk::cs2 {
struct CanFrame;
}
namespace stellwerk::connection {
class StationConnection;
}

namespace stellwerk::ui {

class BusMonitorLogWriter;
class BusMonitorFilter;
class BusMonitorModel;

// A workspace tab that shows every frame on the station's bus as it passes, decoded by the core,
// so that a user can see what the station and other controllers say without a CAN adapter.
class BusMonitorPanel final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(BusMonitorPanel)

public:
    explicit BusMonitorPanel(QWidget* parent = nullptr);
    ~BusMonitorPanel() override;

    // Shows the frames of `station` from now on (null: none). It must outlive the panel or be
    // replaced before it goes.
    void setConnection(connection::StationConnection* station);

    BusMonitorModel* model() const { return m_model; }
    QTableView* table() const { return m_table; }
    // Shows only rows whose message, details or frame contain `text` (case-insensitive); applied at once.
    void setFilterText(const QString& text);
    // Writes every frame seen from now on to a candump log at `path`; returns an error text, empty on
    // success. stopRecording() closes the file.
    QString startRecording(const QString& path);
    void stopRecording();
    bool isRecording() const;
    // Replaces the table's rows with the frames of a candump log; returns an error text, empty on success.
    QString openLog(const QString& path);

protected:
    void changeEvent(QEvent* event) override;

private:
    void receive(const std::vector<cs2::CanFrame>& frames, bool outgoing);
    void chooseRecording(bool start);
    void chooseLog();
    void applyFilter();
    void followNewest();
    void updateCounter();
    void retranslate();

    BusMonitorModel* m_model = nullptr;
    BusMonitorFilter* m_filter = nullptr;
    QTableView* m_table = nullptr;
    QLineEdit* m_filterEdit = nullptr;
    QTimer* m_filterTimer = nullptr;
    QPushButton* m_pauseButton = nullptr;
    QPushButton* m_clearButton = nullptr;
    QPushButton* m_recordButton = nullptr;
    QPushButton* m_openButton = nullptr;
    QLabel* m_historyLabel = nullptr;
    QSpinBox* m_history = nullptr;
    QLabel* m_counter = nullptr;
    QPointer<connection::StationConnection> m_connection;
    std::unique_ptr<BusMonitorLogWriter> m_recorder;
    bool m_followNewest = true;
};

} // namespace stellwerk::ui
