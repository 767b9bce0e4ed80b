#include "Workspace.h"

#include "WindowLayoutSettings.h"

#include <QDockWidget>
#include <QMainWindow>
#include <QTabBar>

namespace stellwerk::ui {

namespace {

// Bumped whenever the set of docks changes, so that an old arrangement is not forced onto new panels.
constexpr int LayoutVersion = 2;

} // namespace

Workspace::Workspace(QMainWindow& window) : QObject(&window), m_window(window) {
    m_window.setDockNestingEnabled(true);
    m_window.setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowNestedDocks |
                            QMainWindow::AllowTabbedDocks | QMainWindow::GroupedDragging);
    m_window.setTabPosition(Qt::AllDockWidgetAreas, QTabWidget::North);
}

QDockWidget* Workspace::addPanel(QWidget* panel, Qt::DockWidgetArea area, QWidget* stackOn) {
    auto* dock = new QDockWidget(&m_window);
    dock->setObjectName(panel->objectName() + QStringLiteral("Dock"));
    dock->setWidget(panel);
    dock->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable |
                      QDockWidget::DockWidgetFloatable);
    // Qt only moves a dock behind another tab out of sight; hiding its panel, as a tab widget does, lets
    // panels stop work nobody sees (the status panel's polling, a view's repaints).
    connect(dock, &QDockWidget::visibilityChanged, panel,
            [panel](bool visible) { panel->setVisible(visible); });
    if (QDockWidget* under = stackOn ? dockOf(stackOn) : nullptr)
        m_window.tabifyDockWidget(under, dock);
    else
        m_window.addDockWidget(area, dock);
    m_docks.append(dock);
    return dock;
}

QDockWidget* Workspace::dockOf(const QWidget* panel) const {
    for (QDockWidget* dock : m_docks) {
        if (panel && dock->widget() == panel)
            return dock;
    }
    return nullptr;
}

QWidget* Workspace::panel(const QString& objectName) const {
    for (QDockWidget* dock : m_docks) {
        if (dock->widget() && dock->widget()->objectName() == objectName)
            return dock->widget();
    }
    return nullptr;
}

bool Workspace::showPanel(QWidget* panel) {
    QDockWidget* dock = dockOf(panel);
    if (!dock)
        return false;
    dock->show();
    dock->raise();
    panel->setFocus(Qt::OtherFocusReason);
    return true;
}

void Workspace::restore() {
    m_initialState = m_window.saveState(LayoutVersion);
    const WindowLayout saved = WindowLayoutSettings::load();
    if (!saved.geometry.isEmpty())
        m_window.restoreGeometry(saved.geometry);
    if (!saved.state.isEmpty())
        m_window.restoreState(saved.state, LayoutVersion);
}

void Workspace::save() const {
    WindowLayoutSettings::save({m_window.saveGeometry(), m_window.saveState(LayoutVersion)});
}

void Workspace::reset() {
    for (QDockWidget* dock : m_docks)
        dock->setFloating(false);
    m_window.restoreState(m_initialState, LayoutVersion);
    for (QDockWidget* dock : m_docks)
        dock->show();
}

} // namespace stellwerk::ui
