#include "shell/KeyList.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QMainWindow>
#include <QRegularExpression>
#include <QScrollBar>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>

namespace stellwerk::ui {

namespace {

QString plainText(const QAction& action) {
    QString text = action.text();
    text.remove(QRegularExpression(QStringLiteral("&(?!&)")));
    return text.remove(QStringLiteral("...")).remove(QChar(0x2026)).trimmed();
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
    QList<KeyUse> uses;
    for (const QAction* action : window.findChildren<QAction*>()) {
        if (action->shortcuts().isEmpty() || action->text().isEmpty())
            continue;
        QStringList keys;
        for (const QKeySequence& key : action->shortcuts())
            keys << key.toString(QKeySequence::NativeText);
        const KeyUse use{keys.join(QStringLiteral(", ")), plainText(*action)};
        if (!uses.contains(use))
            uses << use;
    }
    std::sort(uses.begin(), uses.end(), [](const KeyUse& a, const KeyUse& b) { return a.use < b.use; });
    return uses + panelKeys();
}

QList<KeyUse> KeyList::panelKeys() {
    return {
        {tr("Space"), tr("STOP: track power off for the whole layout (also while a throttle has the keys)")},
        {tr("Alt+1 … Alt+9"), tr("Put the keyboard on throttle 1 … 9")},
        {tr("Up, Down, +, −"), tr("On a throttle: faster, slower")},
        {tr("Page Up, Page Down"), tr("On a throttle: much faster, much slower")},
        {tr("R"), tr("On a throttle: change direction")},
        {tr("0 … 9"), tr("On a throttle: functions F0 … F9")},
        {tr("E"), tr("On a throttle: stop this locomotive")},
        {tr("Escape"), tr("Close a dialog without changing anything")},
    };
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
    // As wide as the longest line (every row in full), as tall as about twenty rows.
    const int width = keys->horizontalHeader()->length() + keys->verticalScrollBar()->sizeHint().width() + 48;
    dialog->resize(std::max(width, 480), keys->verticalHeader()->defaultSectionSize() * 21 + 80);
    return dialog;
}

} // namespace stellwerk::ui
