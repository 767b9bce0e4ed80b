#pragma once

#include "model/UnconfirmedCommands.h"

#include <QMenu>
#include <QPointer>

class QAction;
class QActionGroup;

namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

// Station → After a failed command: what Stellwerk brings back when a station that did not confirm a
// command is heard again (AftermathSettings), and "Bring the layout back in step", the answer to "I don't
// trust what I see": every locomotive gets its confirmed speed (or is stopped) and every state is read again.
class AftermathMenu final : public QMenu {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(AftermathMenu)

public:
    explicit AftermathMenu(QWidget* parent);

    // The railway the choice applies to and the action acts on (null: none, the action is disabled).
    void setRailway(model::Railway* railway);
    QAction* bringBackInStepAction() const { return m_bringBack; }
    model::Aftermath aftermath() const;

signals:
    // A sentence for the status bar: the layout was brought back in step, and how many states were read.
    void report(const QString& sentence);

protected:
    void changeEvent(QEvent* event) override;

private:
    void choose(model::Aftermath aftermath);
    void bringBackInStep();
    void retranslate();

    QPointer<model::Railway> m_railway;
    QAction* m_bringBack;
    QActionGroup* m_group;
    QAction* m_restore;
    QAction* m_stop;
};

} // namespace stellwerk::ui
