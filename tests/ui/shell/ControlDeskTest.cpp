// The main window as a control desk: its panels as docks whose arrangement is kept, the STOP / GO key
// and the keys that stop everything from anywhere, and the status bar's traffic, download and power.

#include "EmbeddedStationSupport.h"
#include "binding/RailwayBinding.h"
#include "common/PowerStatus.h"
#include "connect/ConnectionStatus.h"
#include "connect/StartupProgress.h"
#include "connect/TrafficStatus.h"
#include "model/Railway.h"
#include "monitor/BusMonitorPanel.h"
#include "monitor/FrameDecoderPanel.h"
#include "shell/MainWindow.h"
#include "shell/PassingMessage.h"
#include "shell/Translations.h"
#include "shell/Workspace.h"
#include "status/StatusPanel.h"
#include "stopkeys/StopGoButton.h"
#include "support/StationTestSupport.h"

#include <QAction>
#include <QDockWidget>
#include <QLineEdit>
#include <QSettings>
#include <QStatusBar>
#include <QTableView>
#include <QTest>
#include <gtest/gtest.h>
#include <memory>

using namespace stellwerk;
using namespace stellwerk::ui;
using State = connection::StationConnection::State;
using station::PowerState;

namespace {

constexpr int CommandMs = 5000;

void clearDeskSettings() {
    QSettings(QStringLiteral("Stellwerk"), QStringLiteral("Stellwerk")).clear();
}

// A shown main window without a station, on empty settings.
class ControlDeskTest : public ::testing::Test {
protected:
    void SetUp() override {
        clearDeskSettings();
        ASSERT_TRUE(translations.select(Language::English));
    }
    void TearDown() override { clearDeskSettings(); }

    Translations translations;
};

// The window on the embedded simulated CS2, ready, with track power on.
class ControlDeskOnStationTest : public ControlDeskTest {
protected:
    void SetUp() override {
        ControlDeskTest::SetUp();
        window = std::make_unique<MainWindow>(translations);
        railways = std::make_unique<binding::RailwayBinding>(station);
        QObject::connect(railways.get(), &binding::RailwayBinding::railwayChanged, window.get(),
                         &MainWindow::setRailway);
        window->setConnection(&station);
        window->show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
        station.connectToSimulator();
        ASSERT_TRUE(test::waitForState(station, State::Ready));
        ASSERT_TRUE(QTest::qWaitFor([this] { return power() == PowerState::Running; }, CommandMs));
    }
    void TearDown() override {
        railways.reset();
        window.reset();
        ControlDeskTest::TearDown();
    }
    std::optional<PowerState> power() const {
        return railways->railway() ? railways->railway()->power() : std::nullopt;
    }
    bool powerBecomes(PowerState state) const {
        return QTest::qWaitFor([this, state] { return power() == state; }, CommandMs);
    }
    // Gives `widget` the keyboard focus, as a click into it would.
    void focus(QWidget* widget) {
        window->activateWindow();
        QApplication::setActiveWindow(window.get());
        widget->setFocus(Qt::MouseFocusReason);
        ASSERT_TRUE(QTest::qWaitFor([widget] { return QApplication::focusWidget() == widget; }, 2000));
    }

    connection::StationConnection station{
        support::withEmbeddedStation()}; // outlives the railway and the window
    std::unique_ptr<MainWindow> window;
    std::unique_ptr<binding::RailwayBinding> railways;
};

} // namespace

TEST_F(ControlDeskTest, ClosedAndFloatingPanelsAreRememberedForTheNextStart) {
    {
        MainWindow window(translations);
        window.show();
        window.workspace()->dockOf(window.frameDecoder())->close();
        window.workspace()->dockOf(window.statusPanel())->setFloating(true);
        window.close();
    }
    MainWindow again(translations);
    again.show();
    EXPECT_FALSE(again.workspace()->dockOf(again.frameDecoder())->toggleViewAction()->isChecked());
    EXPECT_TRUE(again.workspace()->dockOf(again.statusPanel())->isFloating());
    EXPECT_TRUE(again.workspace()->dockOf(again.busMonitor())->toggleViewAction()->isChecked());
}

TEST_F(ControlDeskTest, ResetPanelLayoutBringsEveryPanelBack) {
    MainWindow window(translations);
    window.show();
    window.workspace()->dockOf(window.busMonitor())->close();
    window.workspace()->dockOf(window.statusPanel())->setFloating(true);
    window.findChild<QAction*>(QStringLiteral("resetLayoutAction"))->trigger();
    EXPECT_TRUE(window.workspace()->dockOf(window.busMonitor())->isVisible());
    EXPECT_FALSE(window.workspace()->dockOf(window.statusPanel())->isFloating());
}

TEST_F(ControlDeskTest, ShowPanelBringsAStackedPanelToTheFront) {
    MainWindow window(translations);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    EXPECT_TRUE(window.workspace()->showPanel(QStringLiteral("busMonitorPanel")));
    ASSERT_TRUE(QTest::qWaitFor([&] { return window.busMonitor()->isVisible(); }, 2000));
    EXPECT_TRUE(window.workspace()->showPanel(QStringLiteral("frameDecoderPanel")));
    EXPECT_TRUE(QTest::qWaitFor([&] { return window.frameDecoder()->isVisible(); }, 2000));
    EXPECT_TRUE(QTest::qWaitFor([&] { return !window.busMonitor()->isVisible(); },
                                2000)); // stacked under it, and hidden like a tab
    EXPECT_FALSE(window.workspace()->showPanel(QStringLiteral("noSuchPanel")));
}

TEST_F(ControlDeskTest, WithoutAStationStopGoIsDisabledAndTheStatusBarSaysSo) {
    MainWindow window(translations);
    EXPECT_FALSE(window.stopGoButton()->isEnabled());
    EXPECT_EQ(window.stopGoButton()->text(), QStringLiteral("STOP"));
    EXPECT_EQ(window.findChild<PowerStatus*>(QStringLiteral("powerStatus"))->text(),
              QStringLiteral("No station connected"));
    EXPECT_EQ(window.findChild<TrafficStatus*>()->text(), QStringLiteral("Frames in 0 · out 0"));
    EXPECT_FALSE(window.findChild<StartupProgress*>()->isVisibleTo(&window));
}

TEST_F(ControlDeskOnStationTest, StopThenGoSwitchTheTrackPowerAndTheKeyFollows) {
    StopGoButton* key = window->stopGoButton();
    EXPECT_TRUE(key->isEnabled());
    EXPECT_EQ(key->text(), QStringLiteral("STOP"));
    key->click();
    ASSERT_TRUE(powerBecomes(PowerState::Stopped));
    EXPECT_EQ(key->text(), QStringLiteral("TRACK POWER OFF · press to switch on"));
    EXPECT_EQ(window->findChild<PowerStatus*>(QStringLiteral("powerStatus"))->text(),
              QStringLiteral("Track power: off (stop)"));
    key->click();
    ASSERT_TRUE(powerBecomes(PowerState::Running));
    EXPECT_EQ(key->text(), QStringLiteral("STOP"));
}

TEST_F(ControlDeskOnStationTest, SpaceStopsEverythingWhileATableHasTheFocus) {
    auto* table = window->findChild<QTableView*>(QStringLiteral("locomotiveTable"));
    ASSERT_NE(table, nullptr);
    focus(table);
    QTest::keyClick(table, Qt::Key_Space);
    EXPECT_TRUE(powerBecomes(PowerState::Stopped));
}

TEST_F(ControlDeskOnStationTest, EscapeStopsEverythingEvenFromATextField) {
    auto* field = window->busMonitor()->findChild<QLineEdit*>();
    ASSERT_NE(field, nullptr);
    focus(field);
    QTest::keyClick(field, Qt::Key_Escape);
    EXPECT_TRUE(powerBecomes(PowerState::Stopped));
}

TEST_F(ControlDeskOnStationTest, SpaceInATextFieldTypesASpaceAndDoesNotStop) {
    auto* field = window->busMonitor()->findChild<QLineEdit*>();
    ASSERT_NE(field, nullptr);
    focus(field);
    QTest::keyClick(field, Qt::Key_Space);
    EXPECT_EQ(field->text(), QStringLiteral(" "));
    QTest::qWait(300); // a stop would have been confirmed by now
    EXPECT_EQ(power(), PowerState::Running);
}

TEST_F(ControlDeskOnStationTest, StatusBarCountsFramesAndShowsTheTrackPower) {
    auto* traffic = window->findChild<TrafficStatus*>();
    ASSERT_TRUE(
        QTest::qWaitFor([traffic] { return traffic->text() != QStringLiteral("Frames in 0 · out 0"); },
                        TrafficStatus::RefreshMs * 4));
    const auto counters = station.buses().stationCounters();
    EXPECT_GT(counters.framesIn, 0u);
    EXPECT_TRUE(traffic->text().startsWith(QStringLiteral("Frames in "))) << traffic->text().toStdString();
    EXPECT_EQ(window->findChild<PowerStatus*>(QStringLiteral("powerStatus"))->text(),
              QStringLiteral("Track power: on, trains may run"));
}

TEST_F(ControlDeskTest, StartupProgressNamesTheFileAndItsBytesWhileLoading) {
    connection::StationConnection station{support::withEmbeddedStation()};
    MainWindow window(translations);
    window.setConnection(&station);
    window.show();
    auto* progress = window.findChild<StartupProgress*>();
    QStringList seen;
    QObject::connect(&station, &connection::StationConnection::progressChanged, progress,
                     [&] { seen << (progress->isVisibleTo(&window) ? progress->text() : QString()); });
    station.connectToSimulator();
    ASSERT_TRUE(test::waitForState(station, State::Ready));
    EXPECT_FALSE(progress->isVisibleTo(&window));
    const auto download = std::find_if(seen.begin(), seen.end(), [](const QString& text) {
        return text.startsWith(QStringLiteral("lokomotive.cs2: ")) && text.contains(QStringLiteral(" of "));
    });
    ASSERT_NE(download, seen.end()) << seen.join(QLatin1Char('\n')).toStdString();
    EXPECT_TRUE(download->contains(QStringLiteral("(file "))) << download->toStdString();
}

TEST_F(ControlDeskTest, AFailedConnectionSaysWhatToTry) {
    connection::StationConnection station{support::withEmbeddedStation()};
    MainWindow window(translations);
    window.setConnection(&station);
    station.connectTo(QStringLiteral("tcp://"));
    ASSERT_EQ(station.state(), State::Failed);
    EXPECT_TRUE(window.passingMessage()->text().startsWith(QStringLiteral("Try: correct the address")))
        << window.passingMessage()->text().toStdString();
}

TEST_F(ControlDeskTest, StartupProgressDescribesAFileWithoutAnnouncedSize) {
    connection::LoadingProgress progress;
    progress.step = connection::LoadingStep::DownloadingFiles;
    progress.file = QStringLiteral("gleisbild.cs2");
    progress.fileNumber = 4;
    progress.fileCount = 6;
    progress.received = 1500;
    EXPECT_EQ(StartupProgress::describe(progress), QStringLiteral("gleisbild.cs2: 1.5 kB (file 4 of 6)"));
    progress.announced = 3000;
    EXPECT_EQ(StartupProgress::describe(progress),
              QStringLiteral("gleisbild.cs2: 1.5 kB of 3.0 kB (file 4 of 6)"));
}
