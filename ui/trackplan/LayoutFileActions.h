#pragma once

#include <QObject>
#include <QString>

class QAction;
class QMenu;
class QWidget;

namespace stellwerk::ui {

class TrackPlanPanel;

// The layout's file commands, the same in the File menu and on the plan's toolbar: Open layout… (Ctrl+O:
// a folder or a single page file) with the layouts opened recently, and Export layout… (Ctrl+E), whose
// folder dialog starts where the last export went (a folder typed in that is not there yet is made) and
// which says where it wrote the layout.
class LayoutFileActions final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(LayoutFileActions)

public:
    LayoutFileActions(TrackPlanPanel& plan, QWidget& window);

    QAction* openAction() const { return m_open; }
    QAction* exportAction() const { return m_export; }
    QMenu* recentMenu() const { return m_recent; }
    // Opens the layout in `folder` once the plan may open one (unsaved edits settled) and remembers it;
    // a folder that cannot be read is taken off the recent list. False when nothing was opened.
    bool open(const QString& folder);
    // Writes the layout into `folder`, remembers the folder and confirms where it went; false (with the
    // reason on the plan) when it could not be written.
    bool exportTo(const QString& folder);
    void retranslate();

signals:
    // The export into `folder` succeeded (after the confirmation was opened).
    void exported(const QString& folder);

private:
    void chooseFolderToOpen();
    void chooseFolderToExport();
    void fillRecentMenu();

    TrackPlanPanel& m_plan;
    QWidget& m_window;
    QAction* m_open = nullptr;
    QAction* m_export = nullptr;
    QMenu* m_recent = nullptr;
};

} // namespace stellwerk::ui
