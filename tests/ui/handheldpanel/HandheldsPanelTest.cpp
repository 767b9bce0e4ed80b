// The Handhelds panel as a person sees it: on the demo's station (a CS2, their master) it watches and
// shows the demo's MS1 with the locomotive it drives; on a bus whose station is no master, Stellwerk is the
// master, and a stack edited or a name given in the panel reaches the handheld.

#include "handheldpanel/HandheldsPanel.h"

#include "EmbeddedStationSupport.h"
#include "EventLoopWait.h"
#include "binding/RailwayBinding.h"
#include "handheldpanel/HandheldTableModel.h"
#include "mcanhandhelds/HandheldBook.h"
#include "mcanhandhelds/HandheldMaster.h"
#include "model/Railway.h"
#include "shell/MainWindow.h"
#include "shell/Translations.h"
#include "sim/SimulatedBus.h"
#include "sim/SimulatedMs1.h"
#include "support/StationTestSupport.h"

#include <QCheckBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QTableView>
#include <QTest>
#include <QTimer>
#include <functional>
#include <gtest/gtest.h>
#include <memory>

using namespace stellwerk;
using namespace stellwerk::ui;
using State = connection::StationConnection::State;

namespace {

constexpr int WaitMs = 10000;

// Runs the event loop until the condition holds, each event as it comes: a handheld's upgrade is a few
// hundred exchanges, and QTest::qWaitFor sleeps 10 ms between its passes.
bool waitUntil(const std::function<bool()>& condition, int timeoutMs = WaitMs) {
    return support::runEventsUntil(condition, timeoutMs);
}

void clearSettings() {
    QSettings(QStringLiteral("Stellwerk"), QStringLiteral("Stellwerk")).clear();
}

connection::ConnectionSettings withBook(connection::ConnectionSettings settings,
                                        mcanhandhelds::HandheldBook& book) {
    settings.handhelds.book = &book;
    return settings;
}

// The main window with its railway on a connection, shown.
class PanelOnStation : public ::testing::Test {
protected:
    void SetUp() override {
        clearSettings();
        ASSERT_TRUE(translations.select(Language::English));
        window = std::make_unique<MainWindow>(translations);
        railways = std::make_unique<binding::RailwayBinding>(connection);
        QObject::connect(railways.get(), &binding::RailwayBinding::railwayChanged, window.get(),
                         &MainWindow::setRailway);
        window->setConnection(&connection);
        window->resize(1366, 768);
        window->show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
        panel = window->findChild<HandheldsPanel*>();
        ASSERT_NE(panel, nullptr);
    }
    void TearDown() override {
        railways.reset();
        window.reset();
        clearSettings();
    }

    QString cell(int row, int column) const {
        return panel->table().data(panel->table().index(row, column), Qt::DisplayRole).toString();
    }
    bool rowShows(int row, int column, const QString& text) const {
        return panel->table().rowCount() > row && cell(row, column).contains(text);
    }
    void select(int row) {
        auto* view = panel->findChild<QTableView*>(QStringLiteral("handheldTable"));
        view->selectRow(row);
    }

    Translations translations;
    // Where the program keeps the handhelds' stacks and names (app/gui does the same).
    mcanhandhelds::SettingsHandheldBook book{QStringLiteral("Stellwerk"), QStringLiteral("Stellwerk")};
    connection::StationConnection connection{withBook(support::withEmbeddedStation(), book)};
    std::unique_ptr<MainWindow> window;
    std::unique_ptr<binding::RailwayBinding> railways;
    HandheldsPanel* panel = nullptr;
};

TEST_F(PanelOnStation, OnTheDemoStationItWatchesAndShowsTheDemoMs1) {
    connection.connectToSimulator();
    ASSERT_TRUE(test::waitForState(connection, State::Ready));
    ASSERT_TRUE(waitUntil([&] { return rowShows(0, HandheldTableModel::State, "online"); }, WaitMs));
    EXPECT_EQ(cell(0, HandheldTableModel::Name), QStringLiteral("Demo MS1"));
    EXPECT_EQ(cell(0, HandheldTableModel::State), QStringLiteral("online at another master"));
    EXPECT_EQ(panel->roleText(),
              QStringLiteral("Stellwerk only watches the handhelds: the Central Station is their master."));
    auto* choice = panel->findChild<QCheckBox*>(QStringLiteral("actAsMaster"));
    EXPECT_FALSE(choice->isEnabled()) << "no choice while the station is their master";
    EXPECT_FALSE(choice->isChecked());
    ASSERT_TRUE(waitUntil([&] { return !cell(0, HandheldTableModel::Locomotive).isEmpty(); }, WaitMs))
        << "the demo's MS1 takes the first locomotive of its stack";

    ASSERT_TRUE(translations.select(Language::German));
    EXPECT_EQ(cell(0, HandheldTableModel::State), QStringLiteral("an einem anderen Master angemeldet"));
    EXPECT_TRUE(panel->roleText().contains(QStringLiteral("Central Station")))
        << panel->roleText().toStdString();
    EXPECT_TRUE(panel->roleText().contains(QStringLiteral("beobachtet")));
}

// The station's bus with an MS1 but no master on it (a Gleisbox's), behind the station's TCP server.
class PanelAsMaster : public PanelOnStation {
protected:
    void SetUp() override {
        PanelOnStation::SetUp();
        bus.attach(station);
        bus.attach(ms1);
        sim::StationServerSettings settings;
        settings.listenAddress = QHostAddress(QHostAddress::LocalHost);
        settings.udp = false;
        settings.tcpPort = 0;
        server = std::make_unique<sim::StationServer>(station, bus, settings);
        ASSERT_TRUE(server->listen());
        connection.connectTo(QStringLiteral("tcp://127.0.0.1:%1").arg(server->tcpPort()));
        ASSERT_TRUE(test::waitForState(connection, State::Ready));
        ASSERT_TRUE(waitUntil([&] { return connection.handhelds().master()->isMaster(); }, WaitMs));
        ms1.plugIn();
        ASSERT_TRUE(waitUntil([&] { return rowShows(0, HandheldTableModel::State, "online"); }, WaitMs));
        ASSERT_TRUE(waitUntil([&] { return ms1.memory().stack.size() >= 2; }, WaitMs));
        select(0);
    }
    void TearDown() override {
        connection.disconnectFromStation();
        PanelOnStation::TearDown();
    }

    static sim::SimulatedStation::Options noMaster() {
        sim::SimulatedStation::Options options;
        options.handheldMaster = false;
        return options;
    }
    static sim::SimulatedMs1::Options quickMs1() {
        sim::SimulatedMs1::Options options;
        options.identity.uid = 0x000204B3;
        options.identity.name = "KS MS1";
        options.timing.pollPeriod = std::chrono::milliseconds(20);
        return options;
    }

    sim::SimulatedBus bus;
    sim::SimulatedStation station{sim::StationLayout::demo(), noMaster()};
    sim::SimulatedMs1 ms1{quickMs1()};
    std::unique_ptr<sim::StationServer> server;
};

TEST_F(PanelAsMaster, ShowsStellwerkAsMasterAndTheHandheldAsOurs) {
    EXPECT_EQ(panel->roleText(),
              QStringLiteral("Stellwerk is the master of the MS1 handhelds on this bus: plug "
                             "one in to drive with it."));
    EXPECT_EQ(cell(0, HandheldTableModel::State), QStringLiteral("online"));
    EXPECT_EQ(cell(0, HandheldTableModel::Name), QStringLiteral("KS MS1"));
    EXPECT_EQ(cell(0, HandheldTableModel::Node), QStringLiteral("43"));
    auto* choice = panel->findChild<QCheckBox*>(QStringLiteral("actAsMaster"));
    EXPECT_TRUE(choice->isEnabled());
    EXPECT_TRUE(choice->isChecked());
}

TEST_F(PanelAsMaster, ARemovedStackEntryLeavesTheHandheldsStackAndIsRemembered) {
    auto* stack = panel->findChild<QListWidget*>(QStringLiteral("handheldStack"));
    ASSERT_TRUE(waitUntil([&] { return stack->count() >= 2; }, WaitMs));
    const int before = stack->count();
    const QString removed = stack->item(0)->text();
    stack->setCurrentRow(0);
    QTest::mouseClick(panel->findChild<QPushButton*>(QStringLiteral("removeFromStack")), Qt::LeftButton);
    ASSERT_TRUE(waitUntil([&] { return ms1.memory().stack.size() == std::size_t(before - 1); }, WaitMs))
        << "the master told the handheld";
    for (const sim::Ms1Loco& loco : ms1.memory().stack)
        EXPECT_NE(QString::fromStdString(loco.name), removed);
    EXPECT_EQ(stack->count(), before - 1);
    const auto shown = connection.handhelds().master()->handhelds();
    ASSERT_EQ(shown.size(), 1u);
    EXPECT_EQ(shown.front().stack.size(), std::size_t(before - 1));
    const auto saved = book.load(0x000204B3);
    ASSERT_TRUE(saved.has_value()) << "kept in the settings for the next time it logs in";
    EXPECT_EQ(saved->stack, shown.front().stack);
}

TEST_F(PanelAsMaster, ANameGivenInThePanelIsShownForTheHandheld) {
    auto* name = panel->findChild<QLineEdit*>(QStringLiteral("handheldName"));
    ASSERT_TRUE(name->isEnabled());
    name->setText(QStringLiteral("Rangierlok"));
    QTest::mouseClick(panel->findChild<QPushButton*>(QStringLiteral("renameHandheld")), Qt::LeftButton);
    ASSERT_TRUE(waitUntil([&] { return cell(0, HandheldTableModel::Name) == "Rangierlok"; }, WaitMs));
}

TEST_F(PanelAsMaster, UncheckingActAsMasterMakesStellwerkOnlyWatch) {
    auto* choice = panel->findChild<QCheckBox*>(QStringLiteral("actAsMaster"));
    choice->click();
    ASSERT_TRUE(waitUntil([&] { return !connection.handhelds().master()->isMaster(); }, WaitMs));
    EXPECT_EQ(panel->roleText(), QStringLiteral("Stellwerk only watches the handhelds, as chosen."));
    EXPECT_FALSE(QSettings(QStringLiteral("Stellwerk"), QStringLiteral("Stellwerk"))
                     .value(QStringLiteral("mcanhandhelds/actAsMaster"), true)
                     .toBool())
        << "the choice is kept";
    EXPECT_TRUE(choice->isEnabled()) << "the person may choose again";
}

} // namespace
