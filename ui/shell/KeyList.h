#pragma once

#include <QCoreApplication>
#include <QDialog>
#include <QList>
#include <QString>

class QMainWindow;

namespace stellwerk::ui {

// One key (or key range) and what it does.
struct KeyUse {
    QString keys;
    QString use;
    friend bool operator==(const KeyUse&, const KeyUse&) = default;
};

// Help → Keys: every key the desk answers to, in one table. The menu and toolbar commands come from the
// window's own actions (so the list cannot drift from them); the keys that act inside a panel (throttles,
// the plan, the STOP keys) are listed by hand, as the user guide describes them.
class KeyList final {
    Q_DECLARE_TR_FUNCTIONS(stellwerk::ui::KeyList)

public:
    // The window's actions with a shortcut, then the panels' own keys.
    static QList<KeyUse> of(const QMainWindow& window);
    static QList<KeyUse> panelKeys();
    // A dialog showing them (closed with Escape or Close).
    static QDialog* dialog(QMainWindow& window);
};

} // namespace stellwerk::ui
