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

// Help → Keys: every key the desk answers to, in one table. The STOP keys come first (Space, the extra
// STOP key chosen under Station, Escape on the bare window); the menu and toolbar commands come from the
// window's own actions and the bus monitor's keys from its buttons (so the list cannot drift from them);
// the keys that act inside a panel (throttles, turnout keyboard, locomotives) are listed by hand, as the
// user guide describes them. tests/ui/shell checks that every shortcut the window registers is listed.
class KeyList final {
    Q_DECLARE_TR_FUNCTIONS(stellwerk::ui::KeyList)

public:
    // The STOP keys, the window's actions with a shortcut, the panels' own keys, the bus monitor's.
    static QList<KeyUse> of(const QMainWindow& window);
    static QList<KeyUse> stopKeys();
    static QList<KeyUse> commandKeys(const QMainWindow& window);
    static QList<KeyUse> panelKeys();
    static QList<KeyUse> busMonitorKeys(const QMainWindow& window);
    // A dialog showing them (closed with Escape or Close).
    static QDialog* dialog(QMainWindow& window);
};

} // namespace stellwerk::ui
