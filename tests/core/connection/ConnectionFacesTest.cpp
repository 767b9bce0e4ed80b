// The faces a StationConnection hands out (issue 33): each follows the connection as it opens and closes,
// and tells its own users, so that a panel holding one face needs nothing else of the connection.
#include "ConnectionWaits.h"
#include "EmbeddedStationSupport.h"
#include "connection/StationConnection.h"
#include "mcanhandhelds/HandheldMaster.h"
#include "ro/RoProfile.h"

#include <QSignalSpy>
#include <QTest>
#include <gtest/gtest.h>
#include <memory>

using namespace stellwerk;
using connection::ConnectionBuses;
using connection::ConnectionDevices;
using connection::ConnectionHandhelds;
using connection::DeviceSettings;
using connection::HandheldRole;
using connection::StationConnection;
using State = StationConnection::State;

using namespace stellwerk::connection::test;

namespace {

// Nothing listens on port 1 of the loopback: a connection there is open (it keeps trying) but never ready.
const QString Unreachable = QStringLiteral("tcp://127.0.0.1:1");

DeviceSettings oneModule(const std::string& name) {
    DeviceSettings devices;
    connection::RoModuleSettings module;
    module.profile = ro::RoProfile::simulator(1);
    module.profile.name = name;
    module.bus = 1; // not open on any connection here: refused, never started
    devices.roModules.push_back(module);
    return devices;
}

std::string firstModule(const DeviceSettings& devices) {
    return devices.roModules.empty() ? std::string() : devices.roModules.front().profile.name;
}

TEST(ConnectionFaces, TheDevicesFaceTellsWhenAConnectionOpensAndCloses) {
    StationConnection connection{support::withEmbeddedStation()};
    ConnectionDevices& devices = connection.devices();
    QSignalSpy changed(&devices, &ConnectionDevices::devicesChanged);
    EXPECT_FALSE(devices.isOpen());

    connection.connectToSimulator();
    EXPECT_EQ(changed.count(), 1) << "no device sessions, yet the devices in use changed";
    EXPECT_TRUE(devices.isOpen());
    EXPECT_TRUE(devices.onLocalStation());

    connection.disconnectFromStation();
    EXPECT_EQ(changed.count(), 2);
    EXPECT_FALSE(devices.isOpen());
    EXPECT_FALSE(devices.onLocalStation());

    connection.connectTo(Unreachable);
    EXPECT_EQ(changed.count(), 3);
    EXPECT_TRUE(devices.isOpen());
    EXPECT_FALSE(devices.onLocalStation()) << "a station of its own, not the program's";
}

// The local station brings its own devices; the settings serve every other station, and a change to them
// waits for the next connection.
TEST(ConnectionFaces, TheDevicesFaceUsesTheLocalStationsOwnAndKeepsChangesForTheNextConnection) {
    connection::ConnectionSettings settings;
    settings.devices = oneModule("Relais Nord");
    settings.localStationDevices = oneModule("Demo RO");
    StationConnection connection{support::withEmbeddedStation(settings)};
    ConnectionDevices& devices = connection.devices();

    connection.connectToSimulator();
    EXPECT_EQ(firstModule(devices.active()), "Demo RO");
    EXPECT_EQ(firstModule(devices.settings()), "Relais Nord");

    devices.setSettings(oneModule("Relais Süd"));
    EXPECT_EQ(firstModule(devices.active()), "Demo RO") << "the current connection keeps its own";
    EXPECT_EQ(firstModule(devices.settings()), "Relais Süd");

    connection.connectTo(Unreachable);
    EXPECT_EQ(firstModule(devices.active()), "Relais Süd");
    ASSERT_EQ(devices.refusals().size(), 1) << "its bus 1 is not open on this connection";
    EXPECT_TRUE(devices.refusals().front().contains(QStringLiteral("Relais Süd")));
    connection.disconnectFromStation();
    EXPECT_TRUE(devices.refusals().isEmpty());
}

TEST(ConnectionFaces, TheHandheldsFaceBringsAMasterWithEachConnectionAndTakesItAway) {
    StationConnection connection{support::withEmbeddedStation()};
    ConnectionHandhelds& handhelds = connection.handhelds();
    QSignalSpy replaced(&handhelds, &ConnectionHandhelds::masterReplaced);
    EXPECT_EQ(handhelds.master(), nullptr);

    connection.connectToSimulator();
    EXPECT_EQ(replaced.count(), 1);
    mcanhandhelds::HandheldMaster* first = handhelds.master();
    ASSERT_NE(first, nullptr);

    connection.connectToSimulator();
    EXPECT_EQ(replaced.count(), 3) << "the old master went, a new one came";
    EXPECT_NE(handhelds.master(), nullptr);

    connection.disconnectFromStation();
    EXPECT_EQ(replaced.count(), 4);
    EXPECT_EQ(handhelds.master(), nullptr);
}

// The role is the person's choice, not the connection's: chosen while disconnected, the next master
// follows it from its start; chosen while connected, the master follows at once. (A station nobody
// answers on: no Central Station and no other master to defer to.)
TEST(ConnectionFaces, TheRoleChosenOnTheHandheldsFaceHoldsForTheNextMaster) {
    StationConnection connection{support::withEmbeddedStation()};
    ConnectionHandhelds& handhelds = connection.handhelds();
    handhelds.setRole(HandheldRole::Watch);
    connection.connectTo(Unreachable);
    ASSERT_NE(handhelds.master(), nullptr);
    EXPECT_EQ(handhelds.role(), HandheldRole::Watch);
    EXPECT_EQ(handhelds.master()->watching(), mcanhandhelds::Watching::Asked);
    EXPECT_FALSE(handhelds.master()->isMaster());

    handhelds.setRole(HandheldRole::Master);
    EXPECT_TRUE(handhelds.master()->isMaster());
    EXPECT_EQ(handhelds.master()->watching(), mcanhandhelds::Watching::No);

    connection.connectTo(Unreachable);
    EXPECT_EQ(handhelds.role(), HandheldRole::Master);
    EXPECT_TRUE(handhelds.master()->isMaster()) << "the new master takes the role chosen before";
}

// A further bus that goes away and comes back is the same bus: the list stays, only its state changes.
TEST(ConnectionFaces, TheBusesFaceKeepsItsListWhileTheConnectionIsOpen) {
    StationConnection connection{support::withEmbeddedStation()};
    ConnectionBuses& buses = connection.buses();
    QSignalSpy changed(&buses, &ConnectionBuses::busesChanged);
    connection.connectTo(Unreachable, {QStringLiteral("tcp://127.0.0.1:1")});
    EXPECT_EQ(changed.count(), 1);
    ASSERT_EQ(buses.list().size(), 2u);
    EXPECT_TRUE(buses.list()[0].station);
    EXPECT_FALSE(buses.list()[1].station);
    EXPECT_FALSE(buses.isBusConnected(0));
    EXPECT_FALSE(buses.isBusConnected(1));
    EXPECT_EQ(buses.stationCounters().framesIn, 0u);

    connection.disconnectFromStation();
    EXPECT_EQ(changed.count(), 2);
    EXPECT_TRUE(buses.list().empty());
}

// A connection that goes with its owner while open tells nobody: its faces go with it, and a receiver
// asking them back would reach a connection half taken apart.
TEST(ConnectionFaces, AConnectionDestroyedWhileOpenTellsItsFacesUsersNothing) {
    auto connection = std::make_unique<StationConnection>(support::withEmbeddedStation());
    connection->connectToSimulator();
    ASSERT_TRUE(ready(*connection));
    QSignalSpy buses(&connection->buses(), &ConnectionBuses::busesChanged);
    QSignalSpy devices(&connection->devices(), &ConnectionDevices::devicesChanged);
    QSignalSpy handhelds(&connection->handhelds(), &ConnectionHandhelds::masterReplaced);
    connection.reset();
    EXPECT_EQ(buses.count(), 0);
    EXPECT_EQ(devices.count(), 0);
    EXPECT_EQ(handhelds.count(), 0);
}

} // namespace
