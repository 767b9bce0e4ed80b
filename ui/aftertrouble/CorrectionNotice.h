#pragma once

#include "model/UnconfirmedCommands.h"

#include <QPointer>
#include <QTime>
#include <QToolButton>
#include <vector>

class QMenu;

namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

// The status bar's word that Stellwerk brought something back after a command the station did not confirm
// (Railway::stateCorrected): hidden until that happens, then "⚠ 2 set back" until the person has read the
// list (a click shows each with its time) and dismissed it. Each new one is also passed on as a sentence
// for the status bar's message line.
class CorrectionNotice final : public QToolButton {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(CorrectionNotice)

public:
    explicit CorrectionNotice(QWidget* parent = nullptr);

    void setRailway(model::Railway* railway);
    // The sentences of what was brought back since the last dismissal, oldest first.
    QStringList entries() const;
    void dismiss();

signals:
    void corrected(const QString& sentence);

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
    QMenu* m_menu;
};

} // namespace stellwerk::ui
