#include "shell/Workspace.h"

#include "common/WheelGuard.h"
#include "shell/WindowLayoutSettings.h"

#include <QDockWidget>
#include <QMainWindow>
#include <QScrollArea>
#include <QTabBar>

namespace stellwerk::ui {

namespace {

// Bumped whenever the set of docks or the first arrangement changes, so that an old arrangement is not forced
// onto new panels.
constexpr int LayoutVersion = 3;

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
    // A dock narrower or shorter than its panel likes scrolls it rather than forcing the window wider.
    auto* scroll = new QScrollArea(dock);
    scroll->setObjectName(panel->objectName() + QStringLiteral("Scroll"));
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(panel);
    WheelGuard::guard(panel); // the wheel scrolls the panel; it changes a control only the user focused
    dock->setWidget(scroll);
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

QWidget* Workspace::panelOf(const QDockWidget* dock) {
    const auto* scroll = qobject_cast<const QScrollArea*>(dock->widget());
    return scroll ? scroll->widget() : nullptr;
}

QDockWidget* Workspace::dockOf(const QWidget* panel) const {
    for (QDockWidget* dock : m_docks) {
        if (panel && panelOf(dock) == panel)
            return dock;
    }
    return nullptr;
}

QWidget* Workspace::panel(const QString& objectName) const {
    for (QDockWidget* dock : m_docks) {
        if (QWidget* panel = panelOf(dock); panel && panel->objectName() == objectName)
            return panel;
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

bool Workspace::restore() {
    m_initialState = m_window.saveState(LayoutVersion);
    const WindowLayout saved = WindowLayoutSettings::load();
    const bool placed = !saved.geometry.isEmpty() && m_window.restoreGeometry(saved.geometry);
    if (!saved.state.isEmpty())
        m_window.restoreState(saved.state, LayoutVersion);
    return placed;
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
