#pragma once

#include "automation/Schedule.h"

#include <QDialog>
#include <QMessageBox>
#include <functional>
#include <string>
#include <vector>

class QCheckBox;
class QPushButton;
class QTableWidget;

namespace stellwerk::ui {

// The schedule editor: a train's stops (blocks of the track plan, each with its dwell in seconds) added,
// removed and put in order, run once or in a loop. Closing it with changes not taken asks first.
class ScheduleDialog final : public QDialog {
    Q_OBJECT

public:
    // What to do with changes not taken when the dialog is closed: Save, Discard or Cancel.
    using UnsavedQuestion = std::function<QMessageBox::StandardButton(QWidget* dialog)>;

    ScheduleDialog(const QString& train, std::vector<std::string> blocks,
                   const automation::Schedule& schedule, QWidget* parent = nullptr);

    // The schedule as edited; `next` from the first stop when the stops changed.
    automation::Schedule schedule() const;
    bool modified() const { return m_modified; }
    void setUnsavedQuestion(UnsavedQuestion question) { m_question = std::move(question); }

    QTableWidget* stops() const { return m_stops; }
    QCheckBox* loopBox() const { return m_loop; }
    // Adds a stop (the first block, 0 s) after the selected one, or at the end.
    void addStop();
    void removeStop();
    void moveStop(int by);
    void setStop(int row, const std::string& block, double dwellSeconds);

    void reject() override;

private:
    void insertRow(int row, const std::string& block, double dwellSeconds);
    void changed();
    void updateButtons();

    std::vector<std::string> m_blocks;
    automation::Schedule m_original;
    QTableWidget* m_stops = nullptr;
    QCheckBox* m_loop = nullptr;
    QPushButton* m_add = nullptr;
    QPushButton* m_remove = nullptr;
    QPushButton* m_up = nullptr;
    QPushButton* m_down = nullptr;
    UnsavedQuestion m_question;
    bool m_modified = false;
    bool m_stopsChanged = false;
};

} // namespace stellwerk::ui
