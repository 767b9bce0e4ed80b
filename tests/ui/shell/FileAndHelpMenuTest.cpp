// File: Open layout (Ctrl+O), the recent layouts, Export layout (Ctrl+E; remembers its folder, says where it
// wrote) and Quit. Help: the user guide (F1) and the list of keys.

#include "shell/GuideBrowser.h"
#include "shell/KeyList.h"
#include "shell/MainWindow.h"
#include "shell/Translations.h"
#include "trackplan/LayoutFileActions.h"
#include "trackplan/LayoutFileSettings.h"
#include "trackplan/TrackPlanPanel.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QScreen>
#include <QSettings>
#include <QShortcut>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBrowser>
#include <QTimer>
#include <QToolBar>
#include <algorithm>
#include <filesystem>
#include <gtest/gtest.h>
#include <memory>

using namespace stellwerk::ui;

namespace {

QString gbertFolder() {
    return QDir::cleanPath(
        QStringLiteral(STELLWERK_SHARED_DIR "/corpus/GBert__railroad/can2udp/files/maerklin"));
}

class FileAndHelpMenuTest : public ::testing::Test {
protected:
    void SetUp() override {
        settings().clear();
        ASSERT_TRUE(translations.select(Language::English));
        window = std::make_unique<MainWindow>(translations);
    }
    void TearDown() override {
        window.reset();
        settings().clear();
    }
    static QSettings settings() {
        return QSettings(QStringLiteral("Stellwerk"), QStringLiteral("Stellwerk"));
    }
    QMenu* fileMenu() const { return window->findChild<QMenu*>(QStringLiteral("fileMenu")); }
    QStringList recentEntries() const {
        QMenu* recent = window->layoutFiles()->recentMenu();
        emit recent->aboutToShow();
        QStringList texts;
        for (const QAction* action : recent->actions())
            if (!action->isSeparator())
                texts << action->text();
        return texts;
    }

    Translations translations;
    std::unique_ptr<MainWindow> window;
};

} // namespace

TEST_F(FileAndHelpMenuTest, FileHasOpenRecentExportAndQuitWithShortcuts) {
    const QList<QAction*> actions = fileMenu()->actions();
    LayoutFileActions* files = window->layoutFiles();
    ASSERT_EQ(actions.size(), 5);
    EXPECT_EQ(actions[0], files->openAction());
    EXPECT_EQ(actions[1]->menu(), files->recentMenu());
    EXPECT_EQ(actions[2], files->exportAction());
    EXPECT_TRUE(actions[3]->isSeparator());
    EXPECT_EQ(actions[4]->objectName(), QStringLiteral("quitAction"));
    EXPECT_EQ(files->openAction()->shortcut(), QKeySequence(QKeySequence::Open));
    EXPECT_EQ(files->exportAction()->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_E));
    EXPECT_EQ(files->openAction()->text(), QStringLiteral("Open layout..."));
    EXPECT_EQ(files->exportAction()->text(), QStringLiteral("Export layout..."));
    EXPECT_TRUE(window->trackPlan()->findChild<QToolBar*>()->actions().contains(files->openAction()))
        << "the plan's toolbar has the same command";
    EXPECT_EQ(recentEntries(),
              (QStringList{QStringLiteral("No layouts opened yet"), QStringLiteral("Clear the list")}));
}

TEST_F(FileAndHelpMenuTest, AnOpenedLayoutIsOfferedAgainUnderRecent) {
    ASSERT_TRUE(window->layoutFiles()->open(gbertFolder()));
    EXPECT_EQ(LayoutFileSettings::recent(), QStringList{gbertFolder()});
    const QStringList entries = recentEntries();
    ASSERT_EQ(entries.size(), 2);
    EXPECT_EQ(entries[0], QStringLiteral("&1 ") + QDir::toNativeSeparators(gbertFolder()));

    window->trackPlan()->showStationPlan();
    ASSERT_EQ(window->trackPlan()->layout(), nullptr);
    window->layoutFiles()->recentMenu()->actions().first()->trigger();
    ASSERT_NE(window->trackPlan()->layout(), nullptr);
    EXPECT_EQ(window->trackPlan()->pageTabs()->tabText(0), QStringLiteral("karben"));

    window->layoutFiles()->recentMenu()->actions().last()->trigger(); // Clear the list
    EXPECT_TRUE(LayoutFileSettings::recent().isEmpty());
}

TEST_F(FileAndHelpMenuTest, ALayoutThatCannotBeReadLeavesTheRecentList) {
    QTemporaryDir gone;
    ASSERT_TRUE(gone.isValid());
    LayoutFileSettings::rememberOpened(gone.path());
    ASSERT_EQ(LayoutFileSettings::recent().size(), 1);
    EXPECT_FALSE(window->layoutFiles()->open(gone.path())) << "an empty folder holds no layout";
    EXPECT_TRUE(LayoutFileSettings::recent().isEmpty());
    EXPECT_FALSE(window->trackPlan()->problemText().isEmpty());
}

TEST_F(FileAndHelpMenuTest, ExportWritesTheFolderRemembersItAndConfirms) {
    QTemporaryDir target;
    ASSERT_TRUE(target.isValid());
    ASSERT_TRUE(window->layoutFiles()->open(gbertFolder()));
    const QString folder = target.filePath(QStringLiteral("export"));
    ASSERT_TRUE(window->layoutFiles()->exportTo(folder));
    EXPECT_TRUE(QFile::exists(folder + QStringLiteral("/config/gleisbild.cs2")));
    EXPECT_EQ(LayoutFileSettings::exportFolder(), QDir::cleanPath(folder));
    auto* done = window->findChild<QMessageBox*>(QStringLiteral("layoutExportedBox"));
    ASSERT_NE(done, nullptr);
    EXPECT_TRUE(done->isVisible());
    EXPECT_TRUE(done->text().contains(QDir::toNativeSeparators(folder))) << done->text().toStdString();
    done->accept();
}

namespace {

// Answers the folder dialog that opens next: types `typed` into its name field and accepts. A message box
// this brings up is closed, and the dialog too if it stays open, so that a refusal fails the test instead
// of waiting for a person.
void answerFolderDialog(const QString& typed) {
    QTimer::singleShot(0, [typed] {
        auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
        if (!dialog) {
            ADD_FAILURE() << "no folder dialog";
            return;
        }
        auto* boxes = new QTimer(dialog);
        QObject::connect(boxes, &QTimer::timeout, [] {
            if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget()))
                box->reject();
        });
        boxes->start(20);
        dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"))->setText(typed);
        static_cast<QDialog*>(dialog)->accept(); // QFileDialog's own accept() is protected
        if (dialog->isVisible())
            dialog->reject();
    });
}

} // namespace

// Issue 32: Qt's folder dialog refused a folder typed in that did not exist yet ("Directory not found").
TEST_F(FileAndHelpMenuTest, ExportIntoAFolderTypedInThatIsNotThereYetMakesIt) {
    QTemporaryDir target;
    ASSERT_TRUE(target.isValid());
    LayoutFileSettings::rememberExportFolder(target.path());
    ASSERT_TRUE(window->layoutFiles()->open(gbertFolder()));
    const QString typed = target.filePath(QStringLiteral("Anlage 2027/Export"));
    answerFolderDialog(typed);
    window->layoutFiles()->exportAction()->trigger();
    EXPECT_TRUE(QFile::exists(typed + QStringLiteral("/config/gleisbild.cs2")));
    EXPECT_EQ(LayoutFileSettings::exportFolder(), QDir::cleanPath(typed));
    if (auto* done = window->findChild<QMessageBox*>(QStringLiteral("layoutExportedBox")))
        done->accept();
}

TEST_F(FileAndHelpMenuTest, OpenTakesASingleTrackPlanPage) {
    answerFolderDialog(gbertFolder() + QStringLiteral("/config/gleisbilder/karben.cs2"));
    window->layoutFiles()->openAction()->trigger();
    ASSERT_NE(window->trackPlan()->layout(), nullptr);
    ASSERT_EQ(window->trackPlan()->pageTabs()->count(), 1);
    EXPECT_EQ(window->trackPlan()->pageTabs()->tabText(0), QStringLiteral("karben"));
    EXPECT_EQ(LayoutFileSettings::recent().value(0),
              gbertFolder() + QStringLiteral("/config/gleisbilder/karben.cs2"));
}

TEST_F(FileAndHelpMenuTest, AFailedExportConfirmsNothingAndForgetsNothing) {
    QTemporaryDir target;
    ASSERT_TRUE(target.isValid());
    LayoutFileSettings::rememberExportFolder(target.path());
    ASSERT_TRUE(window->layoutFiles()->open(gbertFolder()));
    QFile blocker(target.filePath(QStringLiteral("a-file")));
    ASSERT_TRUE(blocker.open(QIODevice::WriteOnly));
    blocker.close();
    EXPECT_FALSE(window->layoutFiles()->exportTo(blocker.fileName() + QStringLiteral("/export")));
    EXPECT_EQ(window->findChild<QMessageBox*>(QStringLiteral("layoutExportedBox")), nullptr);
    EXPECT_EQ(LayoutFileSettings::exportFolder(), QDir::cleanPath(target.path()));
    EXPECT_FALSE(window->trackPlan()->problemText().isEmpty()) << "the reason is on the plan";
}

TEST_F(FileAndHelpMenuTest, TheKeyListNamesTheMenuCommandsAndThePanelKeys) {
    const QList<KeyUse> keys = KeyList::of(*window);
    const auto has = [&](const QString& key, const QString& use) { return keys.contains(KeyUse{key, use}); };
    EXPECT_TRUE(has(QKeySequence(QKeySequence::Open).toString(QKeySequence::NativeText),
                    QStringLiteral("Open layout")));
    EXPECT_TRUE(has(QStringLiteral("Ctrl+E"), QStringLiteral("Export layout")));
    EXPECT_TRUE(has(window->findChild<QAction*>(QStringLiteral("quitAction"))
                        ->shortcut()
                        .toString(QKeySequence::NativeText),
                    QStringLiteral("Quit")));
    EXPECT_TRUE(has(QStringLiteral("F1"), QStringLiteral("User guide")));
    EXPECT_TRUE(std::any_of(keys.begin(), keys.end(), [](const KeyUse& k) {
        return k.keys == QStringLiteral("Space") && k.use.startsWith(QStringLiteral("STOP"));
    }));
    QDialog* dialog = KeyList::dialog(*window);
    EXPECT_EQ(dialog->findChild<QTableWidget*>(QStringLiteral("keyTable"))->rowCount(), keys.size());
    delete dialog;

    ASSERT_TRUE(translations.select(Language::German));
    QCoreApplication::processEvents();
    const QList<KeyUse> german = KeyList::of(*window);
    EXPECT_TRUE(german.contains(KeyUse{QStringLiteral("Strg+E"), QStringLiteral("Gleisbild exportieren")}));
    EXPECT_TRUE(std::any_of(german.begin(), german.end(),
                            [](const KeyUse& k) { return k.keys == QStringLiteral("Leertaste"); }));
}

namespace {

// Whether a row's keys ("Ctrl+O", "Up, Down, +, −", "Alt+1 … Alt+9") name `key`.
bool covers(const QString& keys, const QString& key) {
    for (const QString& part : keys.split(QStringLiteral(", "))) {
        const QStringList range = part.split(QStringLiteral(" … "));
        if (range.size() == 1 && part == key)
            return true;
        if (range.size() == 2 && key.size() == range[0].size() && key.chopped(1) == range[0].chopped(1) &&
            key.back() >= range[0].back() && key.back() <= range[1].back())
            return true;
    }
    return false;
}

bool listed(const QList<KeyUse>& keys, const QString& key) {
    return std::any_of(keys.begin(), keys.end(), [&](const KeyUse& use) { return covers(use.keys, key); });
}

} // namespace

// Issue 32: Ctrl+S, Delete, the keyboard's Page Up/Down, F12 and the bus monitor's keys were missing, and
// nothing said that Escape on the bare window stops the layout.
TEST_F(FileAndHelpMenuTest, TheKeyListHasEveryShortcutTheWindowRegisters) {
    const QList<KeyUse> keys = KeyList::of(*window);
    int checked = 0;
    for (const QAction* action : window->findChildren<QAction*>())
        for (const QKeySequence& key : action->shortcuts()) {
            const QString text = key.toString(QKeySequence::NativeText);
            EXPECT_TRUE(listed(keys, text)) << text.toStdString() << " of " << action->text().toStdString();
            ++checked;
        }
    for (const QShortcut* shortcut : window->findChildren<QShortcut*>()) {
        const QString text = shortcut->key().toString(QKeySequence::NativeText);
        EXPECT_TRUE(listed(keys, text))
            << text.toStdString() << " of " << shortcut->parent()->objectName().toStdString();
        ++checked;
    }
    const auto* monitor = window->findChild<QWidget*>(QStringLiteral("busMonitorPanel"));
    ASSERT_NE(monitor, nullptr);
    for (const QAbstractButton* button : monitor->findChildren<QAbstractButton*>())
        if (const QKeySequence key = QKeySequence::mnemonic(button->text()); !key.isEmpty()) {
            EXPECT_TRUE(listed(keys, key.toString(QKeySequence::NativeText))) << button->text().toStdString();
            ++checked;
        }
    EXPECT_GT(checked, 20);
    for (const char* key : {"Ctrl+S", "Del", "PgUp", "F12", "Alt+P", "Alt+9"})
        EXPECT_TRUE(listed(keys, QString::fromLatin1(key))) << key;
}

TEST_F(FileAndHelpMenuTest, TheKeyListSaysPlainlyThatEscapeOnTheBareWindowStopsTheLayout) {
    const QList<KeyUse> keys = KeyList::of(*window);
    const auto escape =
        std::find_if(keys.begin(), keys.end(), [](const KeyUse& k) { return k.keys == "Esc"; });
    ASSERT_NE(escape, keys.end());
    EXPECT_EQ(escape->use,
              QStringLiteral(
                  "On the bare window (nothing open on top): STOP, track power off for the whole layout"));
    ASSERT_NE(escape + 1, keys.end());
    EXPECT_EQ((escape + 1)->keys, QStringLiteral("Esc"));
    EXPECT_EQ((escape + 1)->use, QStringLiteral("In a dialog, menu or popup: closes it, and nothing else"));
    const auto extra =
        std::find_if(keys.begin(), keys.end(), [](const KeyUse& k) { return k.keys == "F12"; });
    ASSERT_NE(extra, keys.end());
    EXPECT_TRUE(extra->use.startsWith(QStringLiteral("STOP"))) << extra->use.toStdString();
    EXPECT_LT(escape - keys.begin(), 3) << "the STOP keys come first";
}

TEST_F(FileAndHelpMenuTest, TheUserGuideOpensAtAReadableSize) {
    EXPECT_EQ(GuideBrowser::readableSize(QSize(1366, 728)), QSize(911, 650));
    EXPECT_EQ(GuideBrowser::readableSize(QSize(1920, 1050)), QSize(1280, 700));
    EXPECT_EQ(GuideBrowser::readableSize(QSize(800, 600)), QSize(800, 600)) << "never larger than the screen";
    GuideBrowser guide(GuideBrowser::startPage(), window.get());
    const QSize available = window->screen()->availableGeometry().size();
    EXPECT_EQ(guide.size(), GuideBrowser::readableSize(available));
    EXPECT_GE(guide.width(), std::min(900, available.width()));
    EXPECT_GE(guide.height(), std::min(650, available.height()));
}

TEST_F(FileAndHelpMenuTest, TheUserGuideOpensAtItsContentsAndFollowsLinks) {
    const QString start = GuideBrowser::startPage();
    ASSERT_FALSE(start.isEmpty()) << "a build finds the guide in its source tree";
    GuideBrowser guide(start);
    QTextBrowser* text = guide.browser();
    EXPECT_TRUE(text->toPlainText().startsWith(QStringLiteral("Stellwerk user guide")))
        << text->toPlainText().left(80).toStdString();
    text->setSource(QUrl(QStringLiteral("bus-monitor.md")));
    EXPECT_TRUE(text->toPlainText().startsWith(QStringLiteral("Bus monitor")));
    EXPECT_TRUE(text->isBackwardAvailable());
    text->backward();
    EXPECT_TRUE(text->toPlainText().startsWith(QStringLiteral("Stellwerk user guide")));
}

// docs/screenshots/keys.png, keys-de.png and user-guide.png: Help → Keys and Help → User guide.
TEST_F(FileAndHelpMenuTest, SavesTheDocumentationScreenshotsWhenAsked) {
    const QString folder = qEnvironmentVariable("STELLWERK_SCREENSHOT_DIR");
    if (folder.isEmpty())
        GTEST_SKIP() << "set STELLWERK_SCREENSHOT_DIR to save the screenshots";
    for (const auto& [language, name] :
         {std::pair{Language::English, "keys.png"}, std::pair{Language::German, "keys-de.png"}}) {
        ASSERT_TRUE(translations.select(language));
        QCoreApplication::processEvents(); // the window's actions take their new texts
        QDialog* keys = KeyList::dialog(*window);
        keys->show();
        QTest::qWait(50);
        EXPECT_TRUE(keys->grab().save(folder + QLatin1Char('/') + QLatin1String(name)));
        delete keys;
    }
    ASSERT_TRUE(translations.select(Language::English));
    GuideBrowser guide(GuideBrowser::startPage());
    guide.show();
    QTest::qWait(50);
    EXPECT_TRUE(guide.grab().save(folder + QStringLiteral("/user-guide.png")));
}
