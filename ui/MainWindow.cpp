#include "MainWindow.h"

#include "AboutBox.h"
#include "ApplicationInfo.h"
#include "BusMonitorPanel.h"
#include "ConnectDialog.h"
#include "ConnectionStatus.h"
#include "FrameDecoderPanel.h"
#include "LanguageMenu.h"
#include "LanguageSettings.h"
#include "LayoutOverview.h"
#include "StatusPanel.h"
#include "Translations.h"
#include "connection/StationConnection.h"

#include <QEvent>
#include <QMenuBar>
#include <QStatusBar>
#include <QTabWidget>

namespace stellwerk::ui {

MainWindow::MainWindow(Translations& translations, QWidget* parent)
    : QMainWindow(parent), m_translations(translations) {
    setObjectName(QStringLiteral("mainWindow"));
    setWindowTitle(QStringLiteral("Stellwerk"));
    setWindowIcon(applicationIcon());
    createWorkspace();
    createFileMenu();
    createStationMenu();
    createViewMenu();
    createHelpMenu();
    createStatusBar();
    retranslate();
    resize(1024, 640);
}

void MainWindow::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
    }
    QMainWindow::changeEvent(event);
}

void MainWindow::createWorkspace() {
    m_workspaceTabs = new QTabWidget(this);
    m_workspaceTabs->setObjectName(QStringLiteral("workspaceTabs"));
    m_workspaceTabs->setDocumentMode(true);
    m_workspaceTabs->setMovable(true);
    m_layoutOverview = new LayoutOverview(m_workspaceTabs);
    m_workspaceTabs->addTab(m_layoutOverview, QString());
    // What a running session needs first, the tools for looking at the bus last.
    m_statusPanel = new StatusPanel(m_workspaceTabs);
    m_workspaceTabs->addTab(m_statusPanel, QString());
    m_busMonitor = new BusMonitorPanel(m_workspaceTabs);
    m_workspaceTabs->addTab(m_busMonitor, QString());
    m_frameDecoder = new FrameDecoderPanel(m_workspaceTabs);
    m_workspaceTabs->addTab(m_frameDecoder, QString());
    setCentralWidget(m_workspaceTabs);
}

void MainWindow::createFileMenu() {
    m_fileMenu = menuBar()->addMenu(QString());
    m_fileMenu->setObjectName(QStringLiteral("fileMenu"));
    m_quitAction = m_fileMenu->addAction(QString(), this, &MainWindow::close);
    m_quitAction->setObjectName(QStringLiteral("quitAction"));
    m_quitAction->setShortcut(QKeySequence::Quit);
    m_quitAction->setMenuRole(QAction::QuitRole);
}

void MainWindow::createStationMenu() {
    m_stationMenu = menuBar()->addMenu(QString());
    m_stationMenu->setObjectName(QStringLiteral("stationMenu"));
    m_connectAction = m_stationMenu->addAction(QString(), this, &MainWindow::showConnectDialog);
    m_connectAction->setObjectName(QStringLiteral("connectAction"));
}

void MainWindow::setConnection(connection::StationConnection* station) {
    if (m_connection)
        disconnect(m_connection, nullptr, this, nullptr);
    m_connection = station;
    m_stationStatus->setConnection(station);
    m_busMonitor->setConnection(station);
    if (m_connection) {
        connect(m_connection, &connection::StationConnection::problem, this,
                [this](const QString& message) { showStationProblem(message); });
        connect(m_connection, &QObject::destroyed, this, [this] { m_connection = nullptr; });
    }
}

void MainWindow::setRailway(model::Railway* railway) {
    m_layoutOverview->setRailway(railway);
    m_statusPanel->setRailway(railway);
}

// A failure is already on the station's status line; other problems pass by on the left for a while.
void MainWindow::showStationProblem(const QString& message) {
    if (m_connection && m_connection->state() != connection::StationConnection::State::Failed)
        statusBar()->showMessage(message, 8000);
}

void MainWindow::showConnectDialog() {
    ConnectDialog dialog(m_connection ? m_connection->address() : QString(), this);
    if (dialog.exec() == QDialog::Accepted && m_connection)
        m_connection->connectTo(dialog.url());
}

void MainWindow::createViewMenu() {
    m_viewMenu = menuBar()->addMenu(QString());
    m_viewMenu->setObjectName(QStringLiteral("viewMenu"));
    m_languageMenu = new LanguageMenu(m_translations.current(), m_viewMenu);
    m_viewMenu->addMenu(m_languageMenu);
    connect(m_languageMenu, &LanguageMenu::languageChosen, this, &MainWindow::chooseLanguage);
}

void MainWindow::createHelpMenu() {
    m_helpMenu = menuBar()->addMenu(QString());
    m_helpMenu->setObjectName(QStringLiteral("helpMenu"));
    m_aboutAction = m_helpMenu->addAction(QString(), this, [this] { AboutBox::show(this); });
    m_aboutAction->setObjectName(QStringLiteral("aboutAction"));
    m_aboutAction->setMenuRole(QAction::AboutRole);
}

// Station state is permanent information; the left side stays free for temporary messages.
void MainWindow::createStatusBar() {
    m_stationStatus = new ConnectionStatus(this);
    statusBar()->addPermanentWidget(m_stationStatus);
}

void MainWindow::retranslate() {
    m_fileMenu->setTitle(tr("&File"));
    m_quitAction->setText(tr("&Quit"));
    m_quitAction->setStatusTip(tr("Close the window and end Stellwerk"));
    m_stationMenu->setTitle(tr("&Station"));
    m_connectAction->setText(tr("&Connect…"));
    m_connectAction->setStatusTip(tr("Choose the station to connect to, or the simulated one"));
    m_viewMenu->setTitle(tr("&View"));
    m_helpMenu->setTitle(tr("&Help"));
    m_aboutAction->setText(tr("&About Stellwerk"));
    m_aboutAction->setStatusTip(tr("Show the version of Stellwerk and of Qt"));
    m_workspaceTabs->setTabText(m_workspaceTabs->indexOf(m_layoutOverview), tr("Layout"));
    m_workspaceTabs->setTabText(m_workspaceTabs->indexOf(m_frameDecoder), tr("Frame decoder"));
    m_workspaceTabs->setTabText(m_workspaceTabs->indexOf(m_statusPanel), tr("Status"));
    m_workspaceTabs->setTabText(m_workspaceTabs->indexOf(m_busMonitor), tr("Bus monitor"));
}

void MainWindow::chooseLanguage(Language language) {
    if (!m_translations.select(language)) {
        statusBar()->showMessage(
            tr("The translation \"%1\" could not be loaded.").arg(languageCode(language)));
        m_languageMenu->setCurrent(m_translations.current());
        return;
    }
    LanguageSettings::save(language);
}

} // namespace stellwerk::ui
