#include "shell/KeyList.h"

#include "stopkeys/StopKeySettings.h"

#include <QAbstractButton>
#include <QAction>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QMainWindow>
#include <QRegularExpression>
#include <QScreen>
#include <QScrollBar>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>

namespace stellwerk::ui {

namespace {

QString withoutMnemonic(QString text) {
    text.remove(QRegularExpression(QStringLiteral("&(?!&)")));
    return text.remove(QStringLiteral("...")).remove(QChar(0x2026)).remove(QLatin1Char(':')).trimmed();
}

QString keyText(const QKeySequence& key) {
    return key.toString(QKeySequence::NativeText);
}

QString keyText(Qt::Key key) {
    return keyText(QKeySequence(key));
}

// "A, B": two keys that do the two halves of one row.
QString both(Qt::Key a, Qt::Key b) {
    return keyText(a) + QStringLiteral(", ") + keyText(b);
}

QTableWidget* table(const QList<KeyUse>& uses, QWidget* parent) {
    auto* view = new QTableWidget(int(uses.size()), 2, parent);
    view->setObjectName(QStringLiteral("keyTable"));
    view->setHorizontalHeaderLabels({KeyList::tr("Keys"), KeyList::tr("What they do")});
    for (int row = 0; row < uses.size(); ++row) {
        view->setItem(row, 0, new QTableWidgetItem(uses[row].keys));
        view->setItem(row, 1, new QTableWidgetItem(uses[row].use));
    }
    view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    view->verticalHeader()->hide();
    view->verticalHeader()->setDefaultSectionSize(view->fontMetrics().height() + 8);
    view->resizeColumnsToContents();
    view->setColumnWidth(0, view->columnWidth(0) + view->fontMetrics().averageCharWidth() * 2);
    view->horizontalHeader()->setStretchLastSection(true);
    view->setWordWrap(false);
    view->setAlternatingRowColors(true);
    return view;
}

} // namespace

QList<KeyUse> KeyList::of(const QMainWindow& window) {
    return stopKeys() + commandKeys(window) + panelKeys() + busMonitorKeys(window);
}

// Space from anywhere, the extra key chosen under Station, and Escape where nothing else would close.
QList<KeyUse> KeyList::stopKeys() {
    QList<KeyUse> uses{{tr("Space"), // Qt names it "Space" in every language it does not translate itself
                        tr("STOP: track power off for the whole layout, from anywhere (also while a throttle "
                           "has the keys)")}};
    if (const Qt::Key extra = StopKeySettings::load(); extra != Qt::Key_unknown)
        uses << KeyUse{keyText(extra),
                       tr("STOP, the extra STOP key (choose another under Station → Extra STOP "
                          "key)")};
    uses << KeyUse{keyText(Qt::Key_Escape),
                   tr("On the bare window (nothing open on top): STOP, track power off for the whole layout")}
         << KeyUse{keyText(Qt::Key_Escape), tr("In a dialog, menu or popup: closes it, and nothing else")};
    return uses;
}

// The window's menu and toolbar commands with a shortcut, by name.
QList<KeyUse> KeyList::commandKeys(const QMainWindow& window) {
    QList<KeyUse> uses;
    for (const QAction* action : window.findChildren<QAction*>()) {
        if (action->shortcuts().isEmpty() || action->text().isEmpty())
            continue;
        QStringList keys;
        for (const QKeySequence& key : action->shortcuts())
            keys << keyText(key);
        const KeyUse use{keys.join(QStringLiteral(", ")), withoutMnemonic(action->text())};
        if (!uses.contains(use))
            uses << use;
    }
    std::sort(uses.begin(), uses.end(), [](const KeyUse& a, const KeyUse& b) { return a.use < b.use; });
    return uses;
}

QList<KeyUse> KeyList::panelKeys() {
    return {
        {tr("Alt+1 … Alt+9"), tr("Put the keyboard on throttle 1 … 9")},
        {tr("Up, Down, +, −"), tr("On a throttle: faster, slower")},
        {both(Qt::Key_PageUp, Qt::Key_PageDown), tr("On a throttle: much faster, much slower")},
        {tr("R"), tr("On a throttle: change direction")},
        {tr("0 … 9"), tr("On a throttle: functions F0 … F9")},
        {tr("E"), tr("On a throttle: stop this locomotive")},
        {both(Qt::Key_PageUp, Qt::Key_PageDown), tr("Turnout keyboard: previous page, next page")},
        {both(Qt::Key_Return, Qt::Key_Enter), tr("Turnout keyboard: switch the key that has the focus")},
        {keyText(QKeySequence(QKeySequence::Save)), tr("Locomotives: save the changes to a folder")},
        {keyText(QKeySequence(QKeySequence::Delete)), tr("Locomotives: remove the selected locomotive")},
        {keyText(Qt::Key_F2), tr("Locomotives: change the selected locomotive's Z21 address")},
    };
}

// The bus monitor's buttons and fields are reached with Alt and their underlined letter, which differs
// from language to language: read from the panel as it is now.
QList<KeyUse> KeyList::busMonitorKeys(const QMainWindow& window) {
    const auto* panel = window.findChild<const QWidget*>(QStringLiteral("busMonitorPanel"));
    if (!panel)
        return {};
    QList<KeyUse> uses;
    const auto add = [&](const QString& text) {
        if (const QKeySequence key = QKeySequence::mnemonic(text); !key.isEmpty())
            uses << KeyUse{keyText(key), tr("Bus monitor: %1").arg(withoutMnemonic(text))};
    };
    for (const QAbstractButton* button : panel->findChildren<const QAbstractButton*>())
        add(button->text());
    for (const QLabel* label : panel->findChildren<const QLabel*>())
        if (label->buddy())
            add(label->text());
    std::sort(uses.begin(), uses.end(), [](const KeyUse& a, const KeyUse& b) { return a.keys < b.keys; });
    return uses;
}

QDialog* KeyList::dialog(QMainWindow& window) {
    auto* dialog = new QDialog(&window);
    dialog->setObjectName(QStringLiteral("keyListDialog"));
    dialog->setWindowTitle(tr("Keys"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::reject);
    auto* layout = new QVBoxLayout(dialog);
    QTableWidget* keys = table(of(window), dialog);
    layout->addWidget(keys);
    layout->addWidget(buttons);
    // As wide as the longest line (every row in full), as tall as about twenty rows, within the screen.
    const int width = keys->horizontalHeader()->length() + keys->verticalScrollBar()->sizeHint().width() + 48;
    QSize size(std::max(width, 480), keys->verticalHeader()->defaultSectionSize() * 21 + 80);
    if (const QScreen* screen = window.screen())
        size = size.boundedTo(screen->availableGeometry().size() * 0.9);
    dialog->resize(size);
    return dialog;
}

} // namespace stellwerk::ui
