#include "shell/MainWindow.h"

#include "layout/LayoutOverview.h"
#include "monitor/FrameDecoderPanel.h"
#include "shell/LanguageSettings.h"
#include "shell/Translations.h"
#include "shell/Workspace.h"
#include "trackplan/TrackPlanPanel.h"

#include <QAction>
#include <QCoreApplication>
#include <QDockWidget>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QTreeWidget>
#include <gtest/gtest.h>
#include <memory>

using namespace stellwerk::ui;

namespace {

// A fresh English main window with no stored settings, as on a first run on an English system.
class MainWindowTest : public ::testing::Test {
protected:
    void SetUp() override {
        clearSettings();
        ASSERT_TRUE(translations.select(Language::English));
        window = std::make_unique<MainWindow>(translations);
    }
    void TearDown() override {
        window.reset();
        clearSettings();
    }

    static void clearSettings() {
        QSettings(QStringLiteral("Stellwerk"), QStringLiteral("Stellwerk")).clear();
    }

    // Menu and action texts without their keyboard mnemonic: "&File" -> "File".
    static QString plain(QString text) { return text.remove(QLatin1Char('&')); }

    QMenu* menu(const char* objectName) const { return window->findChild<QMenu*>(QLatin1String(objectName)); }
    QAction* action(const char* objectName) const {
        return window->findChild<QAction*>(QLatin1String(objectName));
    }
    QString menuTitle(const char* objectName) const { return plain(menu(objectName)->title()); }
    QString actionText(const char* objectName) const { return plain(action(objectName)->text()); }
    QString stationStatus() const {
        return window->findChild<QLabel*>(QStringLiteral("stationStatus"))->text();
    }

    // Chooses a language from View -> Language and lets the widgets receive QEvent::LanguageChange.
    void choose(const char* languageAction) {
        action(languageAction)->trigger();
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    }

    Translations translations;
    std::unique_ptr<MainWindow> window;
};

} // namespace

TEST_F(MainWindowTest, TitleIsStellwerk) {
    EXPECT_EQ(window->windowTitle(), QStringLiteral("Stellwerk"));
}

TEST_F(MainWindowTest, HasWindowIcon) {
    EXPECT_FALSE(window->windowIcon().isNull());
}

TEST_F(MainWindowTest, MenuBarHasFileStationViewHelpInThatOrder) {
    QStringList titles;
    for (const QAction* entry : window->menuBar()->actions()) {
        titles << plain(entry->text());
    }
    EXPECT_EQ(titles, (QStringList{QStringLiteral("File"), QStringLiteral("Station"), QStringLiteral("View"),
                                   QStringLiteral("Help")}));
}

TEST_F(MainWindowTest, StationMenuHasConnect) {
    EXPECT_TRUE(menu("stationMenu")->actions().contains(action("connectAction")));
    EXPECT_EQ(actionText("connectAction"), QStringLiteral("Connect…"));
}

TEST_F(MainWindowTest, FileMenuHasQuitWithStandardShortcut) {
    ASSERT_NE(action("quitAction"), nullptr);
    EXPECT_TRUE(menu("fileMenu")->actions().contains(action("quitAction")));
    EXPECT_EQ(actionText("quitAction"), QStringLiteral("Quit"));
    const QKeySequence platform(QKeySequence::Quit);
    EXPECT_EQ(action("quitAction")->shortcut(),
              platform.isEmpty() ? QKeySequence(Qt::CTRL | Qt::Key_Q) : platform);
}

TEST_F(MainWindowTest, QuitClosesTheWindow) {
    window->show();
    ASSERT_TRUE(window->isVisible());
    action("quitAction")->trigger();
    EXPECT_FALSE(window->isVisible());
}

// View -> Blocks is the plan's own toolbar button: one choice, checked in both places.
TEST_F(MainWindowTest, ViewMenuShowsThePlansBlocks) {
    auto* plan = window->findChild<TrackPlanPanel*>();
    ASSERT_NE(plan, nullptr);
    QAction* blocks = action("showBlocksAction");
    ASSERT_NE(blocks, nullptr);
    EXPECT_TRUE(menu("viewMenu")->actions().contains(blocks));
    EXPECT_EQ(actionText("showBlocksAction"), QStringLiteral("Blocks"));
    EXPECT_FALSE(plan->showsBlocks());
    blocks->trigger();
    EXPECT_TRUE(plan->showsBlocks());
    EXPECT_TRUE(plan->blocksAction()->isChecked());
}

TEST_F(MainWindowTest, ViewMenuHasLanguageSubmenuWithEnglishAndDeutsch) {
    QMenu* languages = menu("languageMenu");
    ASSERT_NE(languages, nullptr);
    EXPECT_TRUE(menu("viewMenu")->actions().contains(languages->menuAction()));
    EXPECT_EQ(menuTitle("languageMenu"), QStringLiteral("Language"));
    QStringList names;
    for (const QAction* entry : languages->actions()) {
        names << entry->text();
    }
    EXPECT_EQ(names, (QStringList{QStringLiteral("English"), QStringLiteral("Deutsch")}));
}

TEST_F(MainWindowTest, CurrentLanguageIsChecked) {
    EXPECT_TRUE(action("languageEnglish")->isChecked());
    EXPECT_FALSE(action("languageGerman")->isChecked());
}

TEST_F(MainWindowTest, HelpMenuHasAboutStellwerk) {
    EXPECT_TRUE(menu("helpMenu")->actions().contains(action("aboutAction")));
    EXPECT_EQ(actionText("aboutAction"), QStringLiteral("About Stellwerk"));
}

TEST_F(MainWindowTest, StatusBarSaysNoStationConnected) {
    EXPECT_EQ(stationStatus(), QStringLiteral("No station connected"));
}

TEST_F(MainWindowTest, PanelsAreDocksAroundTheTrackPlan) {
    EXPECT_EQ(window->centralWidget(), static_cast<QWidget*>(window->trackPlan()));
    QStringList names;
    QStringList titles;
    for (QDockWidget* dock : window->workspace()->docks()) {
        names << Workspace::panelOf(dock)->objectName();
        titles << dock->windowTitle();
        EXPECT_EQ(dock->objectName(), Workspace::panelOf(dock)->objectName() + QStringLiteral("Dock"));
        EXPECT_TRUE(menu("panelsMenu")->actions().contains(dock->toggleViewAction()));
    }
    for (const char* panel : {"layoutOverview", "turnoutPanel", "locomotivePanel", "programmingPanel",
                              "throttlePanel", "statusPanel"})
        EXPECT_TRUE(names.contains(QLatin1String(panel))) << panel;
    EXPECT_TRUE(names.contains(QStringLiteral("busMonitorPanel")));
    EXPECT_TRUE(names.contains(QStringLiteral("frameDecoderPanel")));
    EXPECT_TRUE(titles.contains(QStringLiteral("Bus monitor")));
    EXPECT_TRUE(titles.contains(QStringLiteral("Frame decoder")));
}

TEST_F(MainWindowTest, DeutschTranslatesThePanelTitles) {
    choose("languageGerman");
    EXPECT_EQ(window->workspace()->dockOf(window->frameDecoder())->windowTitle(),
              QStringLiteral("Telegramm-Decoder"));
    auto* results = window->findChild<QTreeWidget*>(QStringLiteral("frameResults"));
    ASSERT_NE(results, nullptr);
    EXPECT_EQ(results->headerItem()->text(2), QStringLiteral("Meldung"));
    choose("languageEnglish");
    EXPECT_EQ(window->workspace()->dockOf(window->frameDecoder())->windowTitle(),
              QStringLiteral("Frame decoder"));
}

TEST_F(MainWindowTest, DeutschTranslatesMenusAndStatus) {
    choose("languageGerman");
    EXPECT_EQ(translations.current(), Language::German);
    EXPECT_EQ(menuTitle("fileMenu"), QStringLiteral("Datei"));
    EXPECT_EQ(actionText("quitAction"), QStringLiteral("Beenden"));
    EXPECT_EQ(menuTitle("stationMenu"), QStringLiteral("Zentrale"));
    EXPECT_EQ(actionText("connectAction"), QStringLiteral("Verbinden …"));
    EXPECT_EQ(menuTitle("viewMenu"), QStringLiteral("Ansicht"));
    EXPECT_EQ(menuTitle("languageMenu"), QStringLiteral("Sprache"));
    EXPECT_EQ(menuTitle("helpMenu"), QStringLiteral("Hilfe"));
    EXPECT_EQ(actionText("aboutAction"), QStringLiteral("Über Stellwerk"));
    EXPECT_EQ(stationStatus(), QStringLiteral("Keine Zentrale verbunden"));
    EXPECT_EQ(window->windowTitle(), QStringLiteral("Stellwerk"));
    EXPECT_TRUE(action("languageGerman")->isChecked());
    EXPECT_FALSE(action("languageEnglish")->isChecked());
}

TEST_F(MainWindowTest, EnglishAfterDeutschRestoresTheTexts) {
    choose("languageGerman");
    ASSERT_EQ(menuTitle("fileMenu"), QStringLiteral("Datei"));
    choose("languageEnglish");
    EXPECT_EQ(menuTitle("fileMenu"), QStringLiteral("File"));
    EXPECT_EQ(menuTitle("languageMenu"), QStringLiteral("Language"));
    EXPECT_EQ(stationStatus(), QStringLiteral("No station connected"));
    EXPECT_TRUE(action("languageEnglish")->isChecked());
}

TEST_F(MainWindowTest, ChosenLanguageIsSavedInTheSettings) {
    choose("languageGerman");
    EXPECT_EQ(LanguageSettings::load(), Language::German);
    choose("languageEnglish");
    EXPECT_EQ(LanguageSettings::load(), Language::English);
}

TEST_F(MainWindowTest, NextStartOpensInTheChosenLanguage) {
    choose("languageGerman");
    window.reset();
    ASSERT_TRUE(translations.select(Language::English)); // as after a restart: nothing installed yet

    ASSERT_TRUE(translations.select(LanguageSettings::load()));
    window = std::make_unique<MainWindow>(translations);
    EXPECT_EQ(menuTitle("fileMenu"), QStringLiteral("Datei"));
    EXPECT_TRUE(action("languageGerman")->isChecked());
}

TEST(Translations, BothEmbeddedTranslationsLoad) {
    Translations translations;
    EXPECT_TRUE(translations.select(Language::German));
    EXPECT_EQ(translations.current(), Language::German);
    EXPECT_TRUE(translations.select(Language::English));
    EXPECT_EQ(translations.current(), Language::English);
}
