#pragma once

#include <QList>
#include <QObject>
#include <QString>

class QDockWidget;
class QMainWindow;
class QWidget;

namespace stellwerk::ui {

// The main window's panels as dock widgets a person can move, float, stack and close: where each goes
// first, bringing one to the front, and the arrangement kept between runs (WindowLayoutSettings).
class Workspace final : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(Workspace)

public:
    explicit Workspace(QMainWindow& window);

    // Puts `panel` into a new dock in `area`; with `stackOn`, as a tab on that panel's dock. The dock's
    // object name is the panel's plus "Dock", which is what the saved arrangement refers to.
    QDockWidget* addPanel(QWidget* panel, Qt::DockWidgetArea area, QWidget* stackOn = nullptr);
    // The panel a dock of this workspace holds.
    static QWidget* panelOf(const QDockWidget* dock);
    // The dock holding `panel`, or null.
    QDockWidget* dockOf(const QWidget* panel) const;
    // The panel with this object name, or null.
    QWidget* panel(const QString& objectName) const;
    QList<QDockWidget*> docks() const { return m_docks; }
    // Shows the panel's dock, in front of the docks stacked with it, and gives it the focus.
    bool showPanel(QWidget* panel);
    bool showPanel(const QString& objectName) { return showPanel(panel(objectName)); }

    // Remembers the first arrangement (call once every panel was added), then restores the saved one;
    // true when the window's remembered size and place were restored too.
    bool restore();
    void save() const;
    // Back to the arrangement the panels had when they were added.
    void reset();

private:
    QMainWindow& m_window;
    QList<QDockWidget*> m_docks;
    QByteArray m_initialState;
};

} // namespace stellwerk::ui
