#pragma once

#include "shell/Language.h"

#include <QMainWindow>
#include <QPointer>

class QToolBar;

namespace stellwerk::automation {
class Automation;
}
namespace stellwerk::connection {
class StationConnection;
}
namespace stellwerk::model {
class LayoutInUse;
class Railway;
} // namespace stellwerk::model
namespace stellwerk::operation {
class Operation;
}
namespace stellwerk::phones {
class PhoneServers;
}

namespace stellwerk::ui {

class AftermathMenu;
class AutomaticPanel;
class BusMonitorPanel;
class CorrectionNotice;
class ConnectionStatus;
class EmergencyStopKeys;
class FrameDecoderPanel;
class DevicesPanel;
class HandheldsPanel;
class LanguageMenu;
class LayoutFileActions;
class LayoutOverview;
class LocomotivePanel;
class LocomotivePictureBook;
class PassingMessage;
class PhoneStatus;
class PowerStatus;
class ProgrammingPanel;
class StartupProgress;
class StatusPanel;
class StopGoButton;
class StopKeyMenu;
class ThrottlePanel;
class TrackPlanPanel;
class TrafficStatus;
class Translations;
class TurnoutPanel;
class Workspace;

// The station's main window: menus, the toolbar with the big STOP / GO, the track plan in the middle and
// the other panels of a running session as docks a person arranges (kept between runs), and the status bar
// with the station, its traffic, the configuration download and the track power. Space and the extra STOP
// key stop the layout from anywhere, Escape only where no popup or dialog is open (EmergencyStopKeys).
// Quitting, connecting again and opening another layout ask first when locomotive edits are unsaved.
class MainWindow final : public QMainWindow {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(MainWindow)

public:
    explicit MainWindow(Translations& translations, QWidget* parent = nullptr);

    Workspace* workspace() const { return m_workspace; }
    FrameDecoderPanel* frameDecoder() const { return m_frameDecoder; }
    HandheldsPanel* handhelds() const { return m_handhelds; }
    DevicesPanel* devices() const { return m_devices; }
    AutomaticPanel* automaticPanel() const { return m_automatic; }
    LayoutOverview* layoutOverview() const { return m_layoutOverview; }
    StatusPanel* statusPanel() const { return m_statusPanel; }
    BusMonitorPanel* busMonitor() const { return m_busMonitor; }
    TurnoutPanel* turnoutPanel() const { return m_turnoutPanel; }
    ThrottlePanel* throttlePanel() const { return m_throttlePanel; }
    TrackPlanPanel* trackPlan() const { return m_trackPlan; }
    LayoutFileActions* layoutFiles() const { return m_layoutFiles; }
    LocomotivePanel* locomotivePanel() const { return m_locomotivePanel; }
    ProgrammingPanel* programmingPanel() const { return m_programmingPanel; }
    StopGoButton* stopGoButton() const { return m_stopGo; }
    // The status bar's passing message on its left (a station's problem, what to try).
    PassingMessage* passingMessage() const { return m_message; }
    EmergencyStopKeys* stopKeys() const { return m_stopKeys; }
    AftermathMenu* aftermathMenu() const { return m_aftermath; }
    CorrectionNotice* correctionNotice() const { return m_corrections; }
    // The status bar's "Phones: N" (hidden while no phone server runs).
    PhoneStatus* phoneStatus() const { return m_phoneStatus; }

    // The railway the panels show and STOP / GO acts on (null: none); see RailwayBinding.
    void setRailway(model::Railway* railway);
    // The layout the plan shows and opens and exports folders into (it must outlive the window).
    void setLayoutInUse(model::LayoutInUse* layout);
    // The station connection the status bar shows and Station → Connect… reconnects (null: none). It
    // must outlive the window or be replaced before it goes.
    void setConnection(connection::StationConnection* station);
    // The automatic operation the Automatic panel shows and commands (it must outlive the window).
    void setOperation(operation::Operation* operation);
    // The automation now (Operation::automationChanged; null while there is none), for every panel that
    // shows or places trains: the Automatic panel (and the track plan, once it takes one).
    void setAutomation(automation::Automation* automation);
    connection::StationConnection* stationConnection() const { return m_connection; }
    // The phone servers Station → Phones… sets up and the status bar counts the phones of (null: none; the
    // menu entry is disabled). They must outlive the window. The Handhelds panel does not show the phones
    // yet: this is where it is to be handed the servers once it can show them.
    void setPhoneServers(phones::PhoneServers* phones);
    // Opens Station → Phones…; OK restarts the servers as chosen and keeps the choice.
    void showPhonesDialog();

    // Shows the window where it was left, or at the first start sized to the screen (FirstWindowSize).
    void showAtStart();

    // Opens Station → Connect…; on Connect the choice is stored and the connection reconnects.
    void showConnectDialog();

protected:
    void changeEvent(QEvent* event) override;
    void closeEvent(QCloseEvent* event) override;
    void showEvent(QShowEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    static QRect availableArea();
    void createPanels();
    void arrangePanels();
    void arrangeOnceSized();
    void createToolBar();
    void createFileMenu();
    void createStationMenu();
    void createViewMenu();
    void createHelpMenu();
    void createStatusBar();
    void retranslate();
    void retranslateDocks();
    QString stopKeysText() const;
    void chooseLanguage(Language language);
    void showStationProblem(const QString& message);
    void connectionStateChanged();

    Translations& m_translations;
    Workspace* m_workspace = nullptr;
    LayoutOverview* m_layoutOverview = nullptr;
    HandheldsPanel* m_handhelds = nullptr;
    DevicesPanel* m_devices = nullptr;
    AutomaticPanel* m_automatic = nullptr;
    FrameDecoderPanel* m_frameDecoder = nullptr;
    StatusPanel* m_statusPanel = nullptr;
    BusMonitorPanel* m_busMonitor = nullptr;
    TurnoutPanel* m_turnoutPanel = nullptr;
    ThrottlePanel* m_throttlePanel = nullptr;
    TrackPlanPanel* m_trackPlan = nullptr;
    LocomotivePanel* m_locomotivePanel = nullptr;
    ProgrammingPanel* m_programmingPanel = nullptr;
    QToolBar* m_toolBar = nullptr;
    QToolBar* m_noticeBar = nullptr;
    StopGoButton* m_stopGo = nullptr;
    EmergencyStopKeys* m_stopKeys = nullptr;
    QMenu* m_fileMenu = nullptr;
    QAction* m_quitAction = nullptr;
    QAction* m_guideAction = nullptr;
    QAction* m_keysAction = nullptr;
    LayoutFileActions* m_layoutFiles = nullptr;
    QMenu* m_stationMenu = nullptr;
    QAction* m_connectAction = nullptr;
    QAction* m_phonesAction = nullptr;
    QAction* m_stopAction = nullptr;
    StopKeyMenu* m_stopKeyMenu = nullptr;
    AftermathMenu* m_aftermath = nullptr;
    QMenu* m_viewMenu = nullptr;
    QMenu* m_panelsMenu = nullptr;
    QAction* m_resetLayoutAction = nullptr;
    LanguageMenu* m_languageMenu = nullptr;
    QMenu* m_helpMenu = nullptr;
    QAction* m_aboutAction = nullptr;
    PassingMessage* m_message = nullptr;
    ConnectionStatus* m_stationStatus = nullptr;
    StartupProgress* m_startupProgress = nullptr;
    TrafficStatus* m_traffic = nullptr;
    PowerStatus* m_power = nullptr;
    PhoneStatus* m_phoneStatus = nullptr;
    QPointer<phones::PhoneServers> m_phones;
    CorrectionNotice* m_corrections = nullptr;
    connection::StationConnection* m_connection = nullptr;
    QPointer<LocomotivePictureBook> m_pictures;
    bool m_shownBefore = false;
    bool m_arrangementDue = false;
    bool m_placeRemembered = false;
};

} // namespace stellwerk::ui
