#include "shell/MainWindow.h"

#include "aftertrouble/AftermathMenu.h"
#include "aftertrouble/CorrectionNotice.h"
#include "automatic/AutomaticPanel.h"
#include "common/LocomotivePictureBook.h"
#include "common/PowerStatus.h"
#include "common/ToolIcons.h"
#include "connect/ConnectDialog.h"
#include "connect/ConnectionStatus.h"
#include "connect/StartupProgress.h"
#include "connect/StationUrlSettings.h"
#include "connect/TrafficStatus.h"
#include "connection/StationConnection.h"
#include "devices/DevicesPanel.h"
#include "handheldpanel/HandheldsPanel.h"
#include "keyboard/TurnoutPanel.h"
#include "layout/LayoutOverview.h"
#include "locomotives/LocomotivePanel.h"
#include "monitor/BusMonitorPanel.h"
#include "monitor/FrameDecoderPanel.h"
#include "phones/PhoneServers.h"
#include "phonesettings/PhoneStatus.h"
#include "phonesettings/PhonesDialog.h"
#include "programming/ProgrammingPanel.h"
#include "shell/AboutBox.h"
#include "shell/ApplicationInfo.h"
#include "shell/FirstWindowSize.h"
#include "shell/GuideBrowser.h"
#include "shell/KeyList.h"
#include "shell/LanguageMenu.h"
#include "shell/LanguageSettings.h"
#include "shell/PassingMessage.h"
#include "shell/Translations.h"
#include "shell/WindowLayoutSettings.h"
#include "shell/Workspace.h"
#include "status/StatusPanel.h"
#include "stopkeys/EmergencyStopKeys.h"
#include "stopkeys/StopGoButton.h"
#include "stopkeys/StopKeyMenu.h"
#include "stopkeys/StopKeySettings.h"
#include "throttle/ThrottlePanel.h"
#include "trackplan/LayoutFileActions.h"
#include "trackplan/TrackPlanPanel.h"

#include <QCloseEvent>
#include <QDockWidget>
#include <QEvent>
#include <QGuiApplication>
#include <QMenuBar>
#include <QScreen>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>

namespace stellwerk::ui {

namespace {

// How long a window manager may take to maximize the first window before the panels are arranged anyway.
constexpr int MaximizingMs = 1000;

} // namespace

MainWindow::MainWindow(Translations& translations, QWidget* parent)
    : QMainWindow(parent), m_translations(translations) {
    setObjectName(QStringLiteral("mainWindow"));
    setWindowTitle(QStringLiteral("Stellwerk"));
    setWindowIcon(applicationIcon());
    setGeometry(FirstWindowSize::geometry(availableArea()));
    createPanels();
    createToolBar();
    createFileMenu();
    createStationMenu();
    createViewMenu();
    createHelpMenu();
    createStatusBar();
    retranslate();
    m_placeRemembered = m_workspace->restore();
    m_noticeBar->setVisible(false); // a remembered arrangement never shows an empty strip
}

QRect MainWindow::availableArea() {
    const QScreen* screen = QGuiApplication::primaryScreen();
    return screen ? screen->availableGeometry() : QRect(0, 0, 1366, 768);
}

void MainWindow::showAtStart() {
    if (!m_placeRemembered && FirstWindowSize::opensMaximized(availableArea()))
        showMaximized();
    else
        show();
}

void MainWindow::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
    }
    QMainWindow::changeEvent(event);
}

// Without a remembered arrangement, the panels get the widths their content asks for at this size.
void MainWindow::showEvent(QShowEvent* event) {
    QMainWindow::showEvent(event);
    if (m_shownBefore)
        return;
    m_shownBefore = true;
    m_arrangementDue = WindowLayoutSettings::load().state.isEmpty();
    arrangeOnceSized();
    // A window manager that does not maximize (or none at all) leaves the window as it is.
    QTimer::singleShot(MaximizingMs, this, [this] {
        if (!m_arrangementDue)
            return;
        m_arrangementDue = false;
        arrangePanels();
    });
}

void MainWindow::resizeEvent(QResizeEvent* event) {
    QMainWindow::resizeEvent(event);
    arrangeOnceSized();
}

// A maximized window gets its size from the window manager after it is shown; the panels are arranged
// for that size, not for the smaller one it had before.
void MainWindow::arrangeOnceSized() {
    if (!m_arrangementDue || !isVisible() || (isMaximized() && width() <= normalGeometry().width()))
        return;
    m_arrangementDue = false;
    arrangePanels();
}

// The keyboard with its four columns on the left; one throttle on the right (two where the screen is wide
// enough), reaching down to the status bar; the tables below about a quarter of the height; the plan gets
// the rest.
void MainWindow::arrangePanels() {
    const int throttleColumns = width() >= 1800 ? 2 : 1;
    resizeDocks({m_workspace->dockOf(m_turnoutPanel), m_workspace->dockOf(m_throttlePanel)},
                {m_turnoutPanel->sizeHint().width(), m_throttlePanel->widthFor(throttleColumns)},
                Qt::Horizontal);
    resizeDocks({m_workspace->dockOf(m_layoutOverview)}, {height() * 28 / 100}, Qt::Vertical);
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!m_locomotivePanel->settleUnsavedEdits(tr("quitting"))) {
        event->ignore();
        return;
    }
    m_workspace->save();
    QMainWindow::closeEvent(event);
}

// The track plan in the middle; the keyboard and the locomotive tools on the left, the throttles on the
// right, the overview and the bus tools below.
void MainWindow::createPanels() {
    m_workspace = new Workspace(*this);
    m_trackPlan = new TrackPlanPanel(this);
    setCentralWidget(m_trackPlan);
    m_turnoutPanel = new TurnoutPanel(this);
    m_workspace->addPanel(m_turnoutPanel, Qt::LeftDockWidgetArea);
    m_locomotivePanel = new LocomotivePanel(this);
    m_trackPlan->setOpenGuard(
        [this] { return m_locomotivePanel->settleUnsavedEdits(tr("opening another layout")); });
    m_workspace->addPanel(m_locomotivePanel, Qt::LeftDockWidgetArea, m_turnoutPanel);
    m_programmingPanel = new ProgrammingPanel(this);
    m_workspace->addPanel(m_programmingPanel, Qt::LeftDockWidgetArea, m_turnoutPanel);
    // A decoder registered on the programming page becomes a locomotive of the list at once.
    connect(m_programmingPanel, &ProgrammingPanel::decoderBound, m_locomotivePanel,
            &LocomotivePanel::addBoundDecoder);
    m_throttlePanel = new ThrottlePanel(this);
    m_workspace->addPanel(m_throttlePanel, Qt::RightDockWidgetArea);
    m_statusPanel = new StatusPanel(this);
    m_workspace->addPanel(m_statusPanel, Qt::RightDockWidgetArea, m_throttlePanel);
    m_layoutOverview = new LayoutOverview(this);
    m_workspace->addPanel(m_layoutOverview, Qt::BottomDockWidgetArea);
    m_busMonitor = new BusMonitorPanel(this);
    m_workspace->addPanel(m_busMonitor, Qt::BottomDockWidgetArea, m_layoutOverview);
    m_frameDecoder = new FrameDecoderPanel(this);
    m_workspace->addPanel(m_frameDecoder, Qt::BottomDockWidgetArea, m_layoutOverview);
    m_handhelds = new HandheldsPanel(this);
    m_workspace->addPanel(m_handhelds, Qt::BottomDockWidgetArea, m_layoutOverview);
    m_devices = new DevicesPanel(this);
    m_workspace->addPanel(m_devices, Qt::BottomDockWidgetArea, m_layoutOverview);
    m_automatic = new AutomaticPanel(this);
    m_workspace->addPanel(m_automatic, Qt::BottomDockWidgetArea, m_layoutOverview);
    for (QWidget* front : {static_cast<QWidget*>(m_turnoutPanel), static_cast<QWidget*>(m_throttlePanel),
                           static_cast<QWidget*>(m_layoutOverview)})
        m_workspace->showPanel(front);
    // The throttles are tall: their side reaches down to the status bar, the tables stop beside them.
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
}

void MainWindow::createToolBar() {
    m_toolBar = addToolBar(QString());
    m_toolBar->setObjectName(QStringLiteral("mainToolBar"));
    m_toolBar->setMovable(false);
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_toolBar->toggleViewAction()->setEnabled(false);
    m_stopGo = new StopGoButton(m_toolBar);
    m_toolBar->addWidget(m_stopGo);
    m_stopKeys = new EmergencyStopKeys(this, this);
    m_stopKeys->setExtraKey(StopKeySettings::load());
    connect(m_stopKeys, &EmergencyStopKeys::stopRequested, m_stopGo, &StopGoButton::stopEverything);
    // What was brought back after trouble, in a row of its own below the STOP key until it was read.
    addToolBarBreak();
    m_noticeBar = addToolBar(QString());
    m_noticeBar->setObjectName(QStringLiteral("correctionToolBar"));
    m_noticeBar->setMovable(false);
    m_noticeBar->toggleViewAction()->setEnabled(false);
    m_corrections = new CorrectionNotice(m_noticeBar);
    m_noticeBar->addWidget(m_corrections);
    m_noticeBar->setVisible(false);
    connect(m_corrections, &CorrectionNotice::wanted, m_noticeBar, &QToolBar::setVisible);
}

void MainWindow::createFileMenu() {
    m_fileMenu = menuBar()->addMenu(QString());
    m_fileMenu->setObjectName(QStringLiteral("fileMenu"));
    m_layoutFiles = new LayoutFileActions(*m_trackPlan, *this);
    m_fileMenu->addAction(m_layoutFiles->openAction());
    m_fileMenu->addMenu(m_layoutFiles->recentMenu());
    m_fileMenu->addAction(m_layoutFiles->exportAction());
    m_fileMenu->addSeparator();
    m_quitAction = m_fileMenu->addAction(QString(), this, &MainWindow::close);
    m_quitAction->setObjectName(QStringLiteral("quitAction"));
    // The platform's Quit key; Ctrl+Q where the platform names none (Windows' scheme, the offscreen one).
    const QKeySequence quit(QKeySequence::Quit);
    m_quitAction->setShortcut(quit.isEmpty() ? QKeySequence(Qt::CTRL | Qt::Key_Q) : quit);
    m_quitAction->setMenuRole(QAction::QuitRole);
}

void MainWindow::createStationMenu() {
    m_stationMenu = menuBar()->addMenu(QString());
    m_stationMenu->setObjectName(QStringLiteral("stationMenu"));
    m_connectAction = m_stationMenu->addAction(QString(), this, &MainWindow::showConnectDialog);
    m_connectAction->setObjectName(QStringLiteral("connectAction"));
    ToolIcons::apply(m_connectAction, ToolIcons::Tool::Connect, *this);
    m_toolBar->addSeparator();
    m_toolBar->addAction(m_connectAction);
    m_phonesAction = m_stationMenu->addAction(QString(), this, &MainWindow::showPhonesDialog);
    m_phonesAction->setObjectName(QStringLiteral("phonesAction"));
    m_phonesAction->setEnabled(false);
    m_stationMenu->addSeparator();
    m_stopAction = m_stationMenu->addAction(QString(), m_stopGo, &StopGoButton::stopEverything);
    m_stopAction->setObjectName(QStringLiteral("stopAction"));
    m_stopKeyMenu = new StopKeyMenu(m_stopKeys->extraKey(), m_stationMenu);
    m_stationMenu->addMenu(m_stopKeyMenu);
    connect(m_stopKeyMenu, &StopKeyMenu::keyChosen, this, [this](Qt::Key key) {
        m_stopKeys->setExtraKey(key);
        StopKeySettings::save(key);
        retranslate();
    });
    m_stationMenu->addSeparator();
    m_aftermath = new AftermathMenu(m_stationMenu);
    m_stationMenu->addAction(m_aftermath->bringBackInStepAction());
    m_stationMenu->addMenu(m_aftermath);
    connect(m_aftermath, &AftermathMenu::report, this,
            [this](const QString& sentence) { m_message->showMessage(sentence, 8000); });
}

void MainWindow::setPhoneServers(phones::PhoneServers* phones) {
    m_phones = phones;
    m_phonesAction->setEnabled(phones != nullptr);
    m_phoneStatus->setPhoneServers(phones);
    // The Handhelds panel lists the phones of the servers running now (started and stopped in Settings).
    const auto showPhones = [this] {
        m_handhelds->setPhoneServers(m_phones ? m_phones->z21() : nullptr,
                                     m_phones ? m_phones->withrottle() : nullptr);
    };
    showPhones();
    if (phones)
        connect(phones, &phones::PhoneServers::serversChanged, this, showPhones);
    // The Locomotives panel shows and edits the phones' Z21 addresses, saved with the settings at once.
    m_locomotivePanel->setZ21Addresses(phones ? &phones->addresses() : nullptr, [this] {
        if (m_phones)
            m_phones->saveAddresses();
    });
    if (phones)
        connect(phones, &QObject::destroyed, m_locomotivePanel,
                [panel = m_locomotivePanel] { panel->setZ21Addresses(nullptr, {}); });
}

void MainWindow::showPhonesDialog() {
    if (!m_phones)
        return;
    PhonesDialog dialog(*m_phones, this);
    dialog.exec();
}

void MainWindow::setConnection(connection::StationConnection* station) {
    if (m_connection)
        disconnect(m_connection, nullptr, this, nullptr);
    m_connection = station;
    delete m_pictures;
    m_pictures = station ? new LocomotivePictureBook(&station->pictures(), this) : nullptr;
    m_throttlePanel->setPictures(m_pictures);
    m_locomotivePanel->setPictures(m_pictures);
    m_stationStatus->setConnection(station);
    m_startupProgress->setConnection(station);
    m_traffic->setBuses(station ? &station->buses() : nullptr);
    m_busMonitor->setBuses(station ? &station->buses() : nullptr);
    m_handhelds->setHandhelds(station ? &station->handhelds() : nullptr);
    m_devices->setDevices(station ? &station->devices() : nullptr);
    if (m_connection) {
        connect(m_connection, &connection::StationConnection::problem, this,
                [this](const QString& message) { showStationProblem(message); });
        connect(m_connection, &connection::StationConnection::stateChanged, this,
                &MainWindow::connectionStateChanged);
        connect(m_connection, &QObject::destroyed, this, [this] { m_connection = nullptr; });
    }
}

void MainWindow::setOperation(operation::Operation* operation) {
    m_automatic->setOperation(operation);
}

void MainWindow::setAutomation(automation::Automation* automation) {
    m_automatic->setAutomation(automation);
    m_trackPlan->setAutomation(automation);
}

void MainWindow::setLayoutInUse(model::LayoutInUse* layout) {
    m_trackPlan->setLayoutInUse(layout);
}

void MainWindow::setRailway(model::Railway* railway) {
    m_layoutOverview->setRailway(railway);
    m_statusPanel->setRailway(railway);
    m_turnoutPanel->setRailway(railway);
    m_throttlePanel->setRailway(railway);
    m_trackPlan->setRailway(railway);
    m_locomotivePanel->setRailway(railway);
    m_programmingPanel->setRailway(railway);
    m_handhelds->setRailway(railway);
    m_devices->setRailway(railway);
    m_stopGo->setRailway(railway);
    m_power->setRailway(railway);
    m_aftermath->setRailway(railway);
    m_corrections->setRailway(railway);
}

// A failure is already on the station's status line; other problems pass by on the left for a while,
// with what to try while the station was never reached.
void MainWindow::showStationProblem(const QString& message) {
    using State = connection::StationConnection::State;
    if (!m_connection || m_connection->state() == State::Failed)
        return;
    if (m_connection->state() == State::Connecting)
        m_message->showMessage(
            message + QStringLiteral(" — ") + ConnectionStatus::advice(m_connection->endpoint()), 15000);
    else
        m_message->showMessage(message, 8000);
}

// A failed connection says what to try, and keeps saying it until something changes.
void MainWindow::connectionStateChanged() {
    if (m_connection && m_connection->state() == connection::StationConnection::State::Failed)
        m_message->showMessage(ConnectionStatus::advice(m_connection->endpoint()));
    else if (m_connection && m_connection->state() == connection::StationConnection::State::Ready)
        m_message->clearMessage();
}

void MainWindow::showConnectDialog() {
    ConnectDialog dialog(m_connection ? m_connection->address() : QString(), this);
    dialog.setFurtherBuses(m_connection ? m_connection->furtherBuses() : StationUrlSettings::furtherBuses());
    if (dialog.exec() == QDialog::Accepted && m_connection &&
        m_locomotivePanel->settleUnsavedEdits(tr("connecting again")))
        m_connection->connectTo(dialog.url(), dialog.furtherBuses());
}

void MainWindow::createViewMenu() {
    m_viewMenu = menuBar()->addMenu(QString());
    m_viewMenu->setObjectName(QStringLiteral("viewMenu"));
    m_panelsMenu = m_viewMenu->addMenu(QString());
    m_panelsMenu->setObjectName(QStringLiteral("panelsMenu"));
    for (QDockWidget* dock : m_workspace->docks())
        m_panelsMenu->addAction(dock->toggleViewAction());
    m_resetLayoutAction = m_viewMenu->addAction(QString(), this, [this] {
        m_workspace->reset();
        arrangePanels();
    });
    m_resetLayoutAction->setObjectName(QStringLiteral("resetLayoutAction"));
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(m_trackPlan->blocksAction()); // the plan's own "Blocks", checked with it
    m_viewMenu->addSeparator();
    m_languageMenu = new LanguageMenu(m_translations.current(), m_viewMenu);
    m_viewMenu->addMenu(m_languageMenu);
    connect(m_languageMenu, &LanguageMenu::languageChosen, this, &MainWindow::chooseLanguage);
}

void MainWindow::createHelpMenu() {
    m_helpMenu = menuBar()->addMenu(QString());
    m_helpMenu->setObjectName(QStringLiteral("helpMenu"));
    m_guideAction = m_helpMenu->addAction(QString(), this, [this] { GuideBrowser::showGuide(this); });
    m_guideAction->setObjectName(QStringLiteral("guideAction"));
    m_guideAction->setShortcut(QKeySequence::HelpContents);
    m_keysAction = m_helpMenu->addAction(QString(), this, [this] { KeyList::dialog(*this)->open(); });
    m_keysAction->setObjectName(QStringLiteral("keysAction"));
    m_helpMenu->addSeparator();
    m_aboutAction = m_helpMenu->addAction(QString(), this, [this] { AboutBox::show(this); });
    m_aboutAction->setObjectName(QStringLiteral("aboutAction"));
    m_aboutAction->setMenuRole(QAction::AboutRole);
}

// Station state is permanent information; the left side stays free for passing messages.
void MainWindow::createStatusBar() {
    m_message = new PassingMessage(this);
    statusBar()->addWidget(m_message, 1);
    m_stationStatus = new ConnectionStatus(this);
    m_startupProgress = new StartupProgress(this);
    m_traffic = new TrafficStatus(this);
    m_power = new PowerStatus(this);
    m_phoneStatus = new PhoneStatus(this);
    for (QWidget* part : {static_cast<QWidget*>(m_stationStatus), static_cast<QWidget*>(m_startupProgress),
                          static_cast<QWidget*>(m_traffic), static_cast<QWidget*>(m_phoneStatus),
                          static_cast<QWidget*>(m_power)}) {
        part->setContentsMargins(8, 0, 8, 0); // room between the parts, as between a panel's lamps
        statusBar()->addPermanentWidget(part);
    }
}

void MainWindow::retranslate() {
    m_fileMenu->setTitle(tr("&File"));
    m_layoutFiles->retranslate();
    m_quitAction->setText(tr("&Quit"));
    m_quitAction->setStatusTip(tr("Close the window and end Stellwerk"));
    m_stationMenu->setTitle(tr("&Station"));
    m_connectAction->setText(tr("&Connect…"));
    m_connectAction->setStatusTip(tr("Choose the station to connect to, or the simulated one"));
    m_phonesAction->setText(tr("&Phones and Tablets…"));
    m_phonesAction->setStatusTip(
        tr("Let the Z21 app, a WLANmaus, Engine Driver or WiThrottle drive the layout"));
    m_viewMenu->setTitle(tr("&View"));
    m_helpMenu->setTitle(tr("&Help"));
    m_guideAction->setText(tr("User &guide"));
    m_guideAction->setStatusTip(tr("Read how to use Stellwerk"));
    m_keysAction->setText(tr("&Keys"));
    m_keysAction->setStatusTip(tr("Every key the desk answers to"));
    m_aboutAction->setText(tr("&About Stellwerk"));
    m_aboutAction->setStatusTip(tr("Show the version of Stellwerk and of Qt"));
    // The keys are EmergencyStopKeys' job (from any widget); the menu only names them.
    m_stopAction->setText(tr("&Stop everything") + QStringLiteral("\t") + stopKeysText());
    m_stopAction->setStatusTip(tr("Switch the track power off: every train stops"));
    m_toolBar->setWindowTitle(tr("Stop and go"));
    m_noticeBar->setWindowTitle(tr("Set back after trouble"));
    m_panelsMenu->setTitle(tr("&Panels"));
    m_resetLayoutAction->setText(tr("&Reset panel layout"));
    m_resetLayoutAction->setStatusTip(tr("Put every panel back where it was at the first start"));
    retranslateDocks();
}

// The keys that stop, as the menu names them: "Space, F12" (Escape too, but only where nothing is open).
QString MainWindow::stopKeysText() const {
    const Qt::Key extra = m_stopKeys->extraKey();
    return extra == Qt::Key_unknown
               ? tr("Space")
               : tr("Space, %1").arg(QKeySequence(extra).toString(QKeySequence::NativeText));
}

void MainWindow::retranslateDocks() {
    const auto title = [this](QWidget* panel, const QString& text) {
        if (QDockWidget* dock = m_workspace->dockOf(panel))
            dock->setWindowTitle(text);
    };
    title(m_turnoutPanel, tr("Keyboard"));
    title(m_throttlePanel, tr("Throttles"));
    title(m_locomotivePanel, tr("Locomotives"));
    title(m_programmingPanel, tr("Programming"));
    title(m_statusPanel, tr("Status"));
    title(m_layoutOverview, tr("Overview"));
    title(m_busMonitor, tr("Bus monitor"));
    title(m_frameDecoder, tr("Frame decoder"));
    title(m_automatic, tr("Automatic"));
    title(m_handhelds, tr("Handhelds and phones"));
    title(m_devices, tr("Devices"));
}

void MainWindow::chooseLanguage(Language language) {
    if (!m_translations.select(language)) {
        m_message->showMessage(tr("The translation \"%1\" could not be loaded.").arg(languageCode(language)));
        m_languageMenu->setCurrent(m_translations.current());
        return;
    }
    LanguageSettings::save(language);
}

} // namespace stellwerk::ui
