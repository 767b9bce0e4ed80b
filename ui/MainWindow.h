#pragma once

#include "Language.h"

#include <QMainWindow>

class QTabWidget;

namespace stellwerk::connection {
class StationConnection;
}
namespace stellwerk::model {
class Railway;
}

namespace stellwerk::ui {

class BusMonitorPanel;
class ConnectionStatus;
class FrameDecoderPanel;
class LanguageMenu;
class LayoutOverview;
class StatusPanel;
class Translations;

// The station's main window: menus, the station's status line and the workspace tabs: the layout
// overview first, then the frame decoder, and what later features (throttles, track plan, bus monitor) add.
class MainWindow final : public QMainWindow {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(MainWindow)

public:
    explicit MainWindow(Translations& translations, QWidget* parent = nullptr);

    // Features add their pages here with addTab().
    QTabWidget* workspaceTabs() const { return m_workspaceTabs; }
    FrameDecoderPanel* frameDecoder() const { return m_frameDecoder; }
    LayoutOverview* layoutOverview() const { return m_layoutOverview; }
    StatusPanel* statusPanel() const { return m_statusPanel; }
    BusMonitorPanel* busMonitor() const { return m_busMonitor; }
    // The railway the layout overview and the status page show (null: none); see RailwayBinding.
    void setRailway(model::Railway* railway);
    // The station connection the status bar shows and Station → Connect… reconnects (null: none). It
    // must outlive the window or be replaced before it goes.
    void setConnection(connection::StationConnection* station);
    connection::StationConnection* stationConnection() const { return m_connection; }
    // Opens Station → Connect…; on Connect the choice is stored and the connection reconnects.
    void showConnectDialog();

protected:
    void changeEvent(QEvent* event) override;

private:
    void createWorkspace();
    void createFileMenu();
    void createStationMenu();
    void createViewMenu();
    void createHelpMenu();
    void createStatusBar();
    void retranslate();
    void chooseLanguage(Language language);
    void showStationProblem(const QString& message);

    Translations& m_translations;
    QTabWidget* m_workspaceTabs = nullptr;
    LayoutOverview* m_layoutOverview = nullptr;
    FrameDecoderPanel* m_frameDecoder = nullptr;
    StatusPanel* m_statusPanel = nullptr;
    BusMonitorPanel* m_busMonitor = nullptr;
    QMenu* m_fileMenu = nullptr;
    QAction* m_quitAction = nullptr;
    QMenu* m_stationMenu = nullptr;
    QAction* m_connectAction = nullptr;
    QMenu* m_viewMenu = nullptr;
    LanguageMenu* m_languageMenu = nullptr;
    QMenu* m_helpMenu = nullptr;
    QAction* m_aboutAction = nullptr;
    ConnectionStatus* m_stationStatus = nullptr;
    connection::StationConnection* m_connection = nullptr;
};

} // namespace stellwerk::ui
