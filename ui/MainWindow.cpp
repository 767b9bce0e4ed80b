#include "MainWindow.h"

#include "AboutBox.h"
#include "ApplicationInfo.h"
#include "FrameDecoderPanel.h"
#include "LanguageMenu.h"
#include "LanguageSettings.h"
#include "Translations.h"

#include <QEvent>
#include <QLabel>
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
    m_stationStatus = new QLabel(this);
    m_stationStatus->setObjectName(QStringLiteral("stationStatus"));
    statusBar()->addPermanentWidget(m_stationStatus);
}

void MainWindow::retranslate() {
    m_fileMenu->setTitle(tr("&File"));
    m_quitAction->setText(tr("&Quit"));
    m_quitAction->setStatusTip(tr("Close the window and end Stellwerk"));
    m_viewMenu->setTitle(tr("&View"));
    m_helpMenu->setTitle(tr("&Help"));
    m_aboutAction->setText(tr("&About Stellwerk"));
    m_aboutAction->setStatusTip(tr("Show the version of Stellwerk and of Qt"));
    m_stationStatus->setText(tr("No station connected"));
    m_workspaceTabs->setTabText(m_workspaceTabs->indexOf(m_frameDecoder), tr("Frame decoder"));
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
