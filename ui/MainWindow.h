#pragma once

#include "Language.h"

#include <QMainWindow>

class QLabel;
class QTabWidget;

namespace stellwerk::ui {

class FrameDecoderPanel;
class LanguageMenu;
class Translations;

// The station's main window: menus, the status line and the workspace tabs that later features
// (throttles, track plan, bus monitor) fill.
class MainWindow final : public QMainWindow {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(MainWindow)

public:
    explicit MainWindow(Translations& translations, QWidget* parent = nullptr);

    // Features add their pages here with addTab().
    QTabWidget* workspaceTabs() const { return m_workspaceTabs; }
    FrameDecoderPanel* frameDecoder() const { return m_frameDecoder; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void createWorkspace();
    void createFileMenu();
    void createViewMenu();
    void createHelpMenu();
    void createStatusBar();
    void retranslate();
    void chooseLanguage(Language language);

    Translations& m_translations;
    QTabWidget* m_workspaceTabs = nullptr;
    FrameDecoderPanel* m_frameDecoder = nullptr;
    QMenu* m_fileMenu = nullptr;
    QAction* m_quitAction = nullptr;
    QMenu* m_viewMenu = nullptr;
    LanguageMenu* m_languageMenu = nullptr;
    QMenu* m_helpMenu = nullptr;
    QAction* m_aboutAction = nullptr;
    QLabel* m_stationStatus = nullptr;
};

} // namespace stellwerk::ui
