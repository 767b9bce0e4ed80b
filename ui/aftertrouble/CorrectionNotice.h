#pragma once

#include "model/UnconfirmedCommands.h"

#include <QFrame>
#include <QPointer>
#include <QTime>
#include <vector>

class QLabel;
class QMenu;
class QPushButton;
class QToolButton;

namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

// The amber strip below the STOP key that says what Stellwerk brought back after a command the station
// did not confirm (Railway::stateCorrected): hidden until that happens, then the newest sentence, "⚠ 2 set
// back" with the whole list and each one's time, and Dismiss. It stays until the person dismissed it: it
// says that something on the layout happened that nobody asked for at that moment.
class CorrectionNotice final : public QFrame {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(CorrectionNotice)

public:
    explicit CorrectionNotice(QWidget* parent = nullptr);

    void setRailway(model::Railway* railway);
    // The sentences of what was brought back since the last dismissal, oldest first.
    QStringList entries() const;
    // What the strip says now: the count, and the newest sentence.
    QString summary() const;
    QString newest() const;
    void dismiss();

signals:
    // The strip wants to be shown (something was set back) or hidden (dismissed).
    void wanted(bool shown);

protected:
    void changeEvent(QEvent* event) override;

private:
    struct Entry {
        QTime time;
        model::Correction correction;
    };

    void add(const model::Correction& correction);
    QString sentence(const Entry& entry) const;
    void refresh();
    void fillMenu();

    QPointer<model::Railway> m_railway;
    std::vector<Entry> m_entries;
    QLabel* m_sentence;
    QToolButton* m_list;
    QMenu* m_menu;
    QPushButton* m_dismiss;
};

} // namespace stellwerk::ui
