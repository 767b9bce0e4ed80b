#pragma once

#include "automatic/ScheduleDialog.h"
#include "common/PlaceTrainDialog.h"

#include <QPointer>
#include <QWidget>
#include <cstdint>
#include <optional>

class QLabel;
class QPushButton;
class QTableWidget;

namespace stellwerk::automation {
class Automation;
struct AutomationEvent;
} // namespace stellwerk::automation
namespace stellwerk::operation {
class Operation;
}

namespace stellwerk::ui {

// The Automatic panel: every train of the automatic operation with its block, state (and fault), destination
// and schedule; placing, starting, stopping, handing back and removing a train, its schedule editor;
// Resume after STOP or a restart, and stopping every automatic train at its next stop. The latest event
// shows above the table, and the last fault in red until the next.
class AutomaticPanel final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(AutomaticPanel)

public:
    enum Column { TrainColumn, BlockColumn, StateColumn, DestinationColumn, ScheduleColumn, ColumnCount };

    explicit AutomaticPanel(QWidget* parent = nullptr);

    // The operation it shows and commands (null: none); it must outlive the panel or be replaced first.
    void setOperation(operation::Operation* operation);
    // The automation now (MainWindow forwards Operation::automationChanged); the table follows it.
    void setAutomation(automation::Automation* automation);

    QTableWidget* table() const { return m_table; }
    // The row of a train, or -1.
    int rowOf(std::uint32_t locId) const;
    void selectTrain(std::uint32_t locId);
    std::optional<std::uint32_t> selectedTrain() const;
    QLabel* statusLine() const { return m_status; }
    QLabel* eventLine() const { return m_event; }
    QLabel* faultLine() const { return m_fault; }
    // The dialogs open now (for tests), or null.
    PlaceTrainDialog* placeDialog() const { return m_placeDialog; }
    ScheduleDialog* scheduleDialog() const { return m_scheduleDialog; }

    void openPlaceDialog();
    void openScheduleDialog();

protected:
    void changeEvent(QEvent* event) override;

private:
    void createButtons();
    void retranslate();
    void refresh();
    void fillRow(int row, std::uint32_t locId);
    QString trainName(std::uint32_t locId) const;
    void updateButtons();
    void eventHappened(const automation::AutomationEvent& event);
    void act(const std::optional<std::string>& problem);

    QPointer<operation::Operation> m_operation;
    QLabel* m_status = nullptr;
    QTableWidget* m_table = nullptr;
    QLabel* m_event = nullptr;
    QLabel* m_fault = nullptr;
    QPushButton* m_place = nullptr;
    QPushButton* m_start = nullptr;
    QPushButton* m_stop = nullptr;
    QPushButton* m_handBack = nullptr;
    QPushButton* m_schedule = nullptr;
    QPushButton* m_remove = nullptr;
    QPushButton* m_resume = nullptr;
    QPushButton* m_stopAll = nullptr;
    QPointer<PlaceTrainDialog> m_placeDialog;
    QPointer<ScheduleDialog> m_scheduleDialog;
};

} // namespace stellwerk::ui
