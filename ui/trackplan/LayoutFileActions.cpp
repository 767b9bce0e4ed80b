#include "trackplan/LayoutFileActions.h"

#include "trackplan/LayoutFileDialog.h"
#include "trackplan/LayoutFileSettings.h"
#include "trackplan/TrackPlanPanel.h"

#include <QAction>
#include <QDir>
#include <QMenu>
#include <QMessageBox>

namespace stellwerk::ui {

LayoutFileActions::LayoutFileActions(TrackPlanPanel& plan, QWidget& window)
    : QObject(&window), m_plan(plan), m_window(window), m_open(plan.openAction()),
      m_export(plan.exportAction()), m_recent(new QMenu(&window)) {
    m_open->setShortcut(QKeySequence::Open);
    m_export->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
    for (QAction* action : {m_open, m_export})
        action->setShortcutContext(Qt::WindowShortcut);
    m_recent->setObjectName(QStringLiteral("recentLayoutsMenu"));
    connect(m_open, &QAction::triggered, this, &LayoutFileActions::chooseFolderToOpen);
    connect(m_export, &QAction::triggered, this, &LayoutFileActions::chooseFolderToExport);
    connect(m_recent, &QMenu::aboutToShow, this, &LayoutFileActions::fillRecentMenu);
    retranslate();
}

bool LayoutFileActions::open(const QString& folder) {
    if (!m_plan.mayOpen())
        return false;
    const bool opened = m_plan.openFolder(folder);
    if (opened)
        LayoutFileSettings::rememberOpened(folder);
    else
        LayoutFileSettings::forget(folder);
    fillRecentMenu();
    return opened;
}

bool LayoutFileActions::exportTo(const QString& folder) {
    if (!m_plan.exportTo(folder))
        return false;
    LayoutFileSettings::rememberExportFolder(folder);
    auto* done = new QMessageBox(QMessageBox::Information, tr("Layout exported"),
                                 tr("The layout was written to %1 as a CS2 configuration folder.")
                                     .arg(QDir::toNativeSeparators(folder)),
                                 QMessageBox::Ok, &m_window);
    done->setObjectName(QStringLiteral("layoutExportedBox"));
    done->setAttribute(Qt::WA_DeleteOnClose);
    done->open();
    emit exported(folder);
    return true;
}

void LayoutFileActions::chooseFolderToOpen() {
    if (!m_plan.mayOpen())
        return;
    LayoutFileDialog dialog(LayoutFileDialog::Purpose::Open, LayoutFileSettings::recent().value(0),
                            &m_window);
    if (dialog.exec() == QDialog::Accepted && !dialog.chosen().isEmpty())
        open(dialog.chosen());
}

void LayoutFileActions::chooseFolderToExport() {
    const QString start =
        LayoutFileSettings::exportFolder().isEmpty() ? QDir::homePath() : LayoutFileSettings::exportFolder();
    LayoutFileDialog dialog(LayoutFileDialog::Purpose::Export, start, &m_window);
    if (dialog.exec() == QDialog::Accepted && !dialog.chosen().isEmpty())
        exportTo(dialog.chosen());
}

// One entry per recent layout (keys 1, 2, ... while the menu is open), newest first, and a way to clear
// the list.
void LayoutFileActions::fillRecentMenu() {
    m_recent->clear();
    const QStringList folders = LayoutFileSettings::recent();
    for (qsizetype i = 0; i < folders.size(); ++i) {
        const QString label = QStringLiteral("&%1 %2").arg(i + 1).arg(QDir::toNativeSeparators(folders[i]));
        m_recent->addAction(label, this, [this, folder = folders[i]] { open(folder); });
    }
    if (folders.isEmpty())
        m_recent->addAction(tr("No layouts opened yet"))->setEnabled(false);
    m_recent->addSeparator();
    QAction* clear = m_recent->addAction(tr("Clear the list"), this, [this] {
        LayoutFileSettings::clearRecent();
        fillRecentMenu();
    });
    clear->setEnabled(!folders.isEmpty());
}

void LayoutFileActions::retranslate() {
    m_recent->setTitle(tr("Open &recent layout"));
    fillRecentMenu();
}

} // namespace stellwerk::ui
