// The Throttles panel with phones on it: a Z21 server and a WiThrottle server on loopback in front of a
// railway on the embedded simulated station, a Z21 client and a WiThrottle client of the tests' own each
// driving a locomotive. Each shows as a row with its kind, address, name, locomotive and last message;
// Disconnect removes the row and the station confirms speed 0 for its locomotive. The window is wired as the
// app wires it (PhoneServers, the layout in use), so the status bar counts the phones. In German too, and
// rendered at 1366x768 and 1920x1080 (saved when STELLWERK_SCREENSHOT_DIR names a folder).

#include "EmbeddedStationSupport.h"
#include "EventLoopWait.h"
#include "WiThrottleTestClient.h"
#include "Z21TestClient.h"
#include "binding/RailwayBinding.h"
#include "handheldpanel/HandheldsPanel.h"
#include "handheldpanel/ThrottleTableModel.h"
#include "model/LayoutInUse.h"
#include "model/Railway.h"
#include "model/ThrottlePort.h"
#include "phones/PhoneServers.h"
#include "phones/PhoneSettings.h"
#include "phonesettings/PhoneStatus.h"
#include "shell/MainWindow.h"
#include "shell/Translations.h"
#include "shell/Workspace.h"
#include "support/StationTestSupport.h"
#include "withrottleserver/WiThrottleServer.h"
#include "z21server/Z21Server.h"

#include <QPixmap>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableView>
#include <QTest>
#include <functional>
#include <gtest/gtest.h>
#include <memory>

using namespace stellwerk;
using namespace stellwerk::ui;
using State = connection::StationConnection::State;

namespace {

constexpr int PhoneWaitMs = 10000;
constexpr quint32 Br212 = 0xc003;  // the demo's DCC 3, driven by the Z21 client
constexpr quint32 Taurus = 0xc010; // the demo's DCC 16, driven by the WiThrottle client

bool waitForPhones(const std::function<bool()>& condition, int timeoutMs = PhoneWaitMs) {
    return QTest::qWaitFor(condition, timeoutMs);
}

class ThrottlesPanelTest : public ::testing::Test {
protected:
    void SetUp() override {
        QSettings(QStringLiteral("Stellwerk"), QStringLiteral("Stellwerk")).clear();
        ASSERT_TRUE(translations.select(Language::English));
        window = std::make_unique<MainWindow>(translations);
        railways = std::make_unique<binding::RailwayBinding>(connection, &layout);
        QObject::connect(railways.get(), &binding::RailwayBinding::railwayChanged, phones.get(),
                         &phones::PhoneServers::setRailway);
        QObject::connect(railways.get(), &binding::RailwayBinding::railwayChanged, window.get(),
                         &MainWindow::setRailway);
        window->setPhoneServers(phones.get());
        window->setConnection(&connection);
        window->setLayoutInUse(&layout);
        window->resize(1366, 768);
        window->show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
        panel = window->handhelds();
        connection.connectToSimulator();
        ASSERT_TRUE(test::waitForState(connection, State::Ready));
        ASSERT_TRUE(waitForPhones([&] { return railway() && railway()->isStateReported(); }));
        railway()->go();
        startServers();
    }
    void TearDown() override {
        window.reset();
        railways.reset();
        phones.reset();
        QSettings(QStringLiteral("Stellwerk"), QStringLiteral("Stellwerk")).clear();
    }

    // Both servers on loopback, on free ports, as Station → Phones and Tablets switches them on.
    void startServers() {
        phones::PhoneSettings chosen;
        chosen.z21 = true;
        chosen.z21Listen = {QHostAddress::LocalHost, 0};
        chosen.withrottle = true;
        chosen.withrottleListen = {QHostAddress::LocalHost, 0};
        ASSERT_TRUE(phones->apply(chosen).isEmpty());
        z21 = phones->z21();
        withrottle = phones->withrottle();
    }

    // A Z21 client drives BR 212 and a WiThrottle client ("Annas Handy") Taurus, both confirmed.
    void drive() {
        z21Phone = std::make_unique<z21server::test::Z21TestClient>(z21->port());
        z21Phone->send(z21::SetBroadcastFlags{z21::broadcast::DrivingAndSwitching});
        z21Phone->send(z21::SetLocoDrive{3, {z21::SpeedStepMode::Steps128, true, 60, false}});
        ASSERT_TRUE(waitForPhones([&] { return confirmedSpeed(Br212) > 0; }));
        wiPhone = std::make_unique<withrottleserver::test::WiThrottleTestClient>(withrottle->port());
        ASSERT_TRUE(wiPhone->waitFor<withrottle::HeartbeatInterval>());
        wiPhone->send(withrottle::DeviceName{"Annas Handy"});
        wiPhone->send(withrottle::AcquireLoco{'T', "S16", withrottle::LocoAddress{16, false}, false});
        ASSERT_TRUE(wiPhone->waitForText("MT+S16<;>"));
        wiPhone->send(withrottle::ThrottleAction{'T', "S16", withrottle::SetSpeed{50}});
        ASSERT_TRUE(waitForPhones([&] { return confirmedSpeed(Taurus) > 0; }));
        ASSERT_TRUE(waitForPhones([&] {
            const int row = rowOf(ThrottleRow::Kind::WiThrottle);
            return row >= 0 && cell(row, ThrottleTableModel::Locomotives) == locoName(Taurus) &&
                   cell(row, ThrottleTableModel::LastMessage).contains(QStringLiteral("V50"));
        }));
    }

    model::Railway* railway() const { return railways->railway(); }
    int confirmedSpeed(quint32 loco) const {
        const auto run = railway()->throttlePort().confirmed(loco);
        return run ? run->speed : -1;
    }
    ThrottleTableModel& table() const { return panel->otherThrottles(); }
    QString cell(int row, int column) const {
        return table().data(table().index(row, column), Qt::DisplayRole).toString();
    }
    int rowOf(ThrottleRow::Kind kind) const {
        for (int row = 0; row < table().rowCount(); ++row)
            if (table().row(row)->kind == kind)
                return row;
        return -1;
    }
    QString locoName(quint32 loco) const { return railway()->locomotive(loco)->displayName(); }
    void disconnectRow(int row) {
        panel->findChild<QTableView*>(QStringLiteral("otherThrottleTable"))->selectRow(row);
        auto* button = panel->findChild<QPushButton*>(QStringLiteral("disconnectThrottle"));
        ASSERT_TRUE(button->isEnabled());
        button->click();
    }

    Translations translations;
    connection::StationConnection connection{support::withEmbeddedStation()};
    std::unique_ptr<MainWindow> window;
    std::unique_ptr<binding::RailwayBinding> railways;
    HandheldsPanel* panel = nullptr;
    QSettings settings{QStringLiteral("Stellwerk"), QStringLiteral("Stellwerk")};
    std::unique_ptr<phones::PhoneServers> phones = std::make_unique<phones::PhoneServers>(settings);
    model::LayoutInUse layout;
    z21server::Z21Server* z21 = nullptr;
    withrottleserver::WiThrottleServer* withrottle = nullptr;
    std::unique_ptr<z21server::test::Z21TestClient> z21Phone;
    std::unique_ptr<withrottleserver::test::WiThrottleTestClient> wiPhone;
};

TEST_F(ThrottlesPanelTest, EachPhoneIsARowWithKindAddressLocoAndLastMessage) {
    ASSERT_NO_FATAL_FAILURE(drive());
    ASSERT_TRUE(waitForPhones([&] { return rowOf(ThrottleRow::Kind::Z21) >= 0; }));
    const int z21Row = rowOf(ThrottleRow::Kind::Z21);
    const QString z21Address = QStringLiteral("127.0.0.1:%1").arg(z21Phone->localPort());
    EXPECT_EQ(cell(z21Row, ThrottleTableModel::Kind), QStringLiteral("Z21 app or WLANmaus"));
    EXPECT_EQ(cell(z21Row, ThrottleTableModel::Address), z21Address);
    EXPECT_EQ(cell(z21Row, ThrottleTableModel::Name), QStringLiteral("\u2014")) << "a Z21 client has no name";
    EXPECT_EQ(cell(z21Row, ThrottleTableModel::Locomotives), locoName(Br212));
    EXPECT_TRUE(
        cell(z21Row, ThrottleTableModel::LastMessage).endsWith(QStringLiteral("LAN_X_SET_LOCO_DRIVE 3")))
        << cell(z21Row, ThrottleTableModel::LastMessage).toStdString();

    const int wiRow = rowOf(ThrottleRow::Kind::WiThrottle);
    EXPECT_EQ(cell(wiRow, ThrottleTableModel::Kind), QStringLiteral("WiThrottle or Engine Driver"));
    EXPECT_TRUE(cell(wiRow, ThrottleTableModel::Address).startsWith(QStringLiteral("127.0.0.1:")));
    EXPECT_EQ(cell(wiRow, ThrottleTableModel::Name), QStringLiteral("Annas Handy"));
    EXPECT_EQ(cell(wiRow, ThrottleTableModel::Locomotives), locoName(Taurus));
    EXPECT_TRUE(waitForPhones([&] {
        return cell(rowOf(ThrottleRow::Kind::WiThrottle), ThrottleTableModel::LastMessage)
            .contains(QStringLiteral("MTAS16<;>V50"));
    })) << cell(wiRow, ThrottleTableModel::LastMessage).toStdString();
    EXPECT_TRUE(cell(wiRow, ThrottleTableModel::LastMessage).contains(QLatin1Char(':'))) << "with its time";
    EXPECT_EQ(panel->findChild<QTabWidget*>(QStringLiteral("throttleKinds"))->tabText(1),
              QStringLiteral("Phones and other throttles (2)"));
}

TEST_F(ThrottlesPanelTest, DisconnectRemovesTheRowAndTheStationConfirmsSpeedZero) {
    ASSERT_NO_FATAL_FAILURE(drive());
    ASSERT_TRUE(waitForPhones([&] { return table().rowCount() == 2; }));
    disconnectRow(rowOf(ThrottleRow::Kind::Z21));
    EXPECT_EQ(rowOf(ThrottleRow::Kind::Z21), -1);
    ASSERT_TRUE(waitForPhones([&] { return confirmedSpeed(Br212) == 0; })) << "the station confirms the stop";
    EXPECT_GT(confirmedSpeed(Taurus), 0) << "the other phone still drives";

    disconnectRow(rowOf(ThrottleRow::Kind::WiThrottle));
    EXPECT_EQ(table().rowCount(), 0);
    ASSERT_TRUE(waitForPhones([&] { return confirmedSpeed(Taurus) == 0; }));
    ASSERT_TRUE(waitForPhones([&] { return !wiPhone->connected(); })) << "the connection is closed";
    EXPECT_FALSE(panel->findChild<QPushButton*>(QStringLiteral("disconnectThrottle"))->isEnabled());
}

TEST_F(ThrottlesPanelTest, GermanTexts) {
    ASSERT_NO_FATAL_FAILURE(drive());
    ASSERT_TRUE(translations.select(Language::German));
    auto* disconnect = panel->findChild<QPushButton*>(QStringLiteral("disconnectThrottle"));
    ASSERT_TRUE(waitForPhones([&] { return disconnect->text() == QStringLiteral("Trennen"); }))
        << "widgets are told of the language once the event loop runs";
    const int z21Row = rowOf(ThrottleRow::Kind::Z21);
    EXPECT_EQ(cell(z21Row, ThrottleTableModel::Kind), QStringLiteral("Z21-App oder WLANmaus"));
    EXPECT_EQ(table().headerData(ThrottleTableModel::Locomotives, Qt::Horizontal, Qt::DisplayRole).toString(),
              QStringLiteral("Fährt"));
    EXPECT_EQ(disconnect->toolTip(),
              QStringLiteral("Das ausgewählte Handy trennen: seine Loks werden angehalten"));
    EXPECT_EQ(cell(rowOf(ThrottleRow::Kind::WiThrottle), ThrottleTableModel::Kind),
              QStringLiteral("WiThrottle oder Engine Driver"));
    EXPECT_EQ(panel->findChild<QTabWidget*>(QStringLiteral("throttleKinds"))->tabText(1),
              QStringLiteral("Handys und andere Handregler (2)"));
}

// The whole window with the Throttles panel in front, two phones driving, in both languages and sizes.
TEST_F(ThrottlesPanelTest, ScreenshotWithTwoPhones) {
    ASSERT_NO_FATAL_FAILURE(drive());
    const QString folder = qEnvironmentVariable("STELLWERK_SCREENSHOT_DIR");
    ASSERT_TRUE(window->workspace()->showPanel(panel));
    panel->findChild<QTabWidget*>(QStringLiteral("throttleKinds"))->setCurrentIndex(1);
    for (const Language language : {Language::English, Language::German}) {
        ASSERT_TRUE(translations.select(language));
        for (const QSize size : {QSize(1366, 768), QSize(1920, 1080)}) {
            window->resize(size);
            QTest::qWait(50);
            const QString suffix = (language == Language::German ? QStringLiteral("-de") : QString()) +
                                   (size.width() == 1920 ? QStringLiteral("-1920x1080") : QString());
            const QPixmap shot = window->grab();
            EXPECT_EQ(shot.size(), size);
            EXPECT_EQ(window->phoneStatus()->text(), language == Language::German
                                                         ? QStringLiteral("Handys: 2")
                                                         : QStringLiteral("Phones: 2"));
            EXPECT_TRUE(window->phoneStatus()->isVisible()) << "the status bar counts the phones";
            if (!folder.isEmpty()) {
                EXPECT_TRUE(shot.save(folder + QStringLiteral("/throttles-panel%1.png").arg(suffix)));
            }
        }
    }
    EXPECT_EQ(table().rowCount(), 2);
}

} // namespace
