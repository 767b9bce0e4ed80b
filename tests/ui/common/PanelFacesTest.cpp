// Each panel is handed the one face of the connection it needs, never the whole connection (issue 33):
// the build proves that it cannot be given more, and the tests show that it follows its face alone as the
// connection opens and closes.

#include "EmbeddedStationSupport.h"
#include "connect/TrafficStatus.h"
#include "connection/StationConnection.h"
#include "devices/DeviceTableModel.h"
#include "devices/DevicesPanel.h"
#include "handheldpanel/HandheldTableModel.h"
#include "handheldpanel/HandheldsPanel.h"
#include "monitor/BusMonitorModel.h"
#include "monitor/BusMonitorPanel.h"
#include "shell/Translations.h"

#include <QSettings>
#include <QTest>
#include <gtest/gtest.h>

using namespace stellwerk;
using namespace stellwerk::ui;
using connection::StationConnection;

namespace {

// Whether a panel offers a way to be handed the whole connection.
template <typename Panel>
concept TakesTheWholeConnection = requires(Panel& panel, StationConnection* connection) {
    panel.setConnection(connection);
}
|| requires(Panel& panel, StationConnection* connection) {
    panel.setBuses(connection);
}
|| requires(Panel& panel, StationConnection* connection) {
    panel.setDevices(connection);
}
|| requires(Panel& panel, StationConnection* connection) {
    panel.setHandhelds(connection);
};

static_assert(!TakesTheWholeConnection<BusMonitorPanel>);
static_assert(!TakesTheWholeConnection<TrafficStatus>);
static_assert(!TakesTheWholeConnection<DevicesPanel>);
static_assert(!TakesTheWholeConnection<DeviceTableModel>);
static_assert(!TakesTheWholeConnection<HandheldsPanel>);
static_assert(std::is_invocable_v<decltype(&BusMonitorPanel::setBuses), BusMonitorPanel&,
                                  connection::ConnectionBuses*>);
static_assert(std::is_invocable_v<decltype(&TrafficStatus::setBuses), TrafficStatus&,
                                  const connection::ConnectionBuses*>);
static_assert(
    std::is_invocable_v<decltype(&DevicesPanel::setDevices), DevicesPanel&, connection::ConnectionDevices*>);
static_assert(std::is_invocable_v<decltype(&HandheldsPanel::setHandhelds), HandheldsPanel&,
                                  connection::ConnectionHandhelds*>);

constexpr int ReadyMs = 10000;

class PanelFaces : public ::testing::Test {
protected:
    void SetUp() override {
        QSettings(QStringLiteral("Stellwerk"), QStringLiteral("Stellwerk")).clear();
        ASSERT_TRUE(translations.select(Language::English));
    }
    bool connectToTheDemo() {
        connection.connectToSimulator();
        return QTest::qWaitFor([this] { return connection.state() == StationConnection::State::Ready; },
                               ReadyMs);
    }

    Translations translations;
    StationConnection connection{support::withEmbeddedStation([] {
        connection::ConnectionSettings settings;
        settings.localStationDevices = connection::DeviceSettings::embeddedDemo();
        return settings;
    }())};
};

TEST_F(PanelFaces, TheHandheldsPanelLetsGoOfTheMasterWhenTheConnectionCloses) {
    HandheldsPanel panel;
    panel.setHandhelds(&connection.handhelds());
    const QString notConnected = QStringLiteral("Not connected: no handhelds to show.");
    EXPECT_EQ(panel.roleText(), notConnected);
    ASSERT_TRUE(connectToTheDemo());
    EXPECT_NE(panel.roleText(), notConnected);
    ASSERT_TRUE(QTest::qWaitFor([&] { return panel.table().rowCount() == 1; }, ReadyMs)) << "the demo's MS1";

    connection.disconnectFromStation();
    EXPECT_EQ(panel.roleText(), notConnected) << "told by the face at once, not by the station's state";
    EXPECT_TRUE(QTest::qWaitFor([&] { return panel.table().rowCount() == 0; }, ReadyMs))
        << "the demo's MS1 went";
}

TEST_F(PanelFaces, TheDevicesPanelSaysNotConnectedOnceTheConnectionCloses) {
    DevicesPanel panel;
    panel.setDevices(&connection.devices());
    EXPECT_EQ(panel.summaryText(), QStringLiteral("Not connected."));
    ASSERT_TRUE(connectToTheDemo());
    EXPECT_TRUE(panel.summaryText().contains(QStringLiteral("RO modules:")))
        << panel.summaryText().toStdString();
    EXPECT_TRUE(panel.noteText().contains(QStringLiteral("demo station brings its own devices")));
    EXPECT_GT(panel.table().rowCount(), 0) << "the demo's RO module";

    connection.disconnectFromStation();
    EXPECT_EQ(panel.summaryText(), QStringLiteral("Not connected."));
    EXPECT_TRUE(panel.noteText().contains(QStringLiteral("next connection")))
        << "no longer on the demo: what is added serves the next connection";
}

TEST_F(PanelFaces, TheBusMonitorNamesTheBusesOfItsFace) {
    BusMonitorPanel panel;
    panel.setBuses(&connection.buses());
    EXPECT_EQ(panel.model()->busName(0), QStringLiteral("can0"));
    ASSERT_TRUE(connectToTheDemo());
    EXPECT_EQ(panel.model()->busCount(), 2) << "the demo's station bus and its device bus";
    EXPECT_EQ(panel.model()->busName(0), QStringLiteral("station"));
    EXPECT_EQ(panel.model()->busName(1), connection.buses().list().at(1).place);

    connection.disconnectFromStation();
    EXPECT_EQ(panel.model()->busName(0), QStringLiteral("can0")) << "no buses: none named";
}

} // namespace
