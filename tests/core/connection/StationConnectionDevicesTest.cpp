// The device protocols of a connection (issue 15): the settings say which bus carries the OpenRailCAN
// central and which RO modules; the connection opens their sessions on those buses when they connect,
// refuses a module its bus cannot carry, and tears the sessions down and makes them anew when a bus (the
// station's or a further one) goes away and comes back. The devices are simulated peers behind real
// loopback sockets.

#include "ConnectionWaits.h"
#include "DeviceBusPeer.h"
#include "EmbeddedStationSupport.h"
#include "connection/DeviceSessions.h"
#include "connection/StationConnection.h"
#include "sim/SimulatedOrcDevices.h"
#include "sim/SimulatedRoModule.h"
#include "sim/SimulatedStation.h"
#include "sim/StationLayout.h"
#include "sim/StationServer.h"

#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <gtest/gtest.h>

using namespace stellwerk;
using connection::ConnectionBuses;
using connection::ConnectionDevices;
using connection::DeviceSettings;
using connection::RoModuleSettings;
using connection::StationConnection;
using romodule::RoModuleSession;
using State = StationConnection::State;

using namespace stellwerk::connection::test;

namespace {

constexpr std::uint32_t DecoderUid = 0x3A2E0007;
constexpr std::uint32_t EncoderUid = 0x3A2E0008;

RoModuleSettings simulatorModule(std::uint16_t n, int bus) {
    RoModuleSettings module;
    module.profile = ro::RoProfile::simulator(n);
    module.profile.name = "RO " + std::to_string(n);
    module.bus = bus;
    module.pollPeriod = std::chrono::milliseconds(100);
    return module;
}

// The central and RO module 1 on bus `bus`.
DeviceSettings devicesOn(int bus) {
    DeviceSettings devices;
    devices.orc.on = true;
    devices.orc.bus = bus;
    devices.roModules.push_back(simulatorModule(1, bus));
    return devices;
}

connection::ConnectionSettings settingsWith(DeviceSettings devices) {
    connection::ConnectionSettings settings;
    settings.session.liveness.interval = std::chrono::milliseconds(200);
    settings.devices = std::move(devices);
    return settings;
}

// The devices every rig puts on its bus: RO module 1, an ORC decoder and an ORC encoder.
struct SimulatedDevices {
    template <typename Bus>
    void attachTo(Bus& bus) {
        decoder.plugIn();
        encoder.plugIn();
        bus.attach(module);
        bus.attach(decoder);
        bus.attach(encoder);
    }
    sim::SimulatedRoModule module{ro::RoProfile::simulator(1)};
    sim::SimulatedOrcDecoder decoder{DecoderUid};
    sim::SimulatedOrcEncoder encoder{EncoderUid};
};

bool devicesWork(const StationConnection& connection) {
    RoModuleSession* module = connection.devices().roModule(QStringLiteral("RO 1"));
    orccentral::OrcSession* orc = connection.devices().orcSession();
    return module && module->state() == RoModuleSession::State::Online && module->outputs() && orc &&
           orc->device(DecoderUid) && orc->device(EncoderUid) &&
           orc->device(DecoderUid)->state == orccentral::OrcDevice::State::Online;
}

// The embedded station on bus 0 and a gateway with the devices on bus 1.
struct FurtherBusRig {
    FurtherBusRig() : connection(support::withEmbeddedStation(settingsWith(devicesOn(1)))) {
        devices.attachTo(gateway.bus);
    }
    bool start() {
        if (!gateway.listen())
            return false;
        connection.connectTo(QString(), {gateway.url()});
        return waitUntil([&] { return connection.state() == State::Ready && devicesWork(connection); });
    }
    support::DeviceBusPeer gateway;
    SimulatedDevices devices;
    StationConnection connection;
};

TEST(StationConnectionDevices, TheSettingsAreSavedAndReadBack) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    QSettings file(dir.filePath(QStringLiteral("stellwerk.ini")), QSettings::IniFormat);
    DeviceSettings saved = devicesOn(1);
    saved.orc.session.busId = 0x0001;
    RoModuleSettings shortReads = simulatorModule(2, 0);
    shortReads.profile.ids = {0x123, 0x124, false};
    shortReads.profile.changeFlags.reset();
    shortReads.profile.readRequestSize = ro::ReadRequestSize::Four;
    shortReads.pollPeriod = std::chrono::milliseconds(500);
    saved.roModules.push_back(shortReads);
    saved.save(file);
    file.sync();

    QSettings again(file.fileName(), QSettings::IniFormat);
    const DeviceSettings read = DeviceSettings::load(again);
    EXPECT_TRUE(read.orc.on);
    EXPECT_EQ(read.orc.bus, 1);
    EXPECT_EQ(read.orc.session.busId, 0x0001);
    ASSERT_EQ(read.roModules.size(), 2u);
    for (std::size_t n = 0; n < 2; ++n) {
        EXPECT_EQ(read.roModules[n].profile.name, saved.roModules[n].profile.name);
        EXPECT_EQ(read.roModules[n].profile.ids, saved.roModules[n].profile.ids);
        EXPECT_EQ(read.roModules[n].profile.outputs, saved.roModules[n].profile.outputs);
        EXPECT_EQ(read.roModules[n].profile.inputs, saved.roModules[n].profile.inputs);
        EXPECT_EQ(read.roModules[n].profile.changeFlags, saved.roModules[n].profile.changeFlags);
        EXPECT_EQ(read.roModules[n].profile.readRequestSize, saved.roModules[n].profile.readRequestSize);
        EXPECT_EQ(read.roModules[n].bus, saved.roModules[n].bus);
        EXPECT_EQ(read.roModules[n].pollPeriod, saved.roModules[n].pollPeriod);
    }

    DeviceSettings fewer;
    fewer.save(again);
    EXPECT_TRUE(DeviceSettings::load(again).roModules.empty()) << "a removed module stays removed";
    EXPECT_FALSE(DeviceSettings::load(again).orc.on);
}

TEST(StationConnectionDevices, TheBusProfilesExpectTheDevicesWiredToThem) {
    DeviceSettings devices = devicesOn(0);
    devices.roModules.push_back(simulatorModule(2, 1));
    const busreading::BusProfile station =
        connection::deviceBusProfile(devices, 0, busreading::BusProfile::centralStation());
    EXPECT_TRUE(station.expects(busreading::Protocol::Orc));
    EXPECT_TRUE(station.expects(busreading::Protocol::Cs2));
    EXPECT_FALSE(station.expects(busreading::Protocol::Mcan))
        << "M-CAN and ORC cannot be told apart (notes O26)";
    EXPECT_EQ(station.roModules(), std::vector{ro::RoProfile::simulator(1).ids});
    const busreading::BusProfile further = connection::deviceBusProfile(devices, 1, busreading::BusProfile{});
    EXPECT_FALSE(further.expects(busreading::Protocol::Orc));
    EXPECT_EQ(further.roModules(), std::vector{ro::RoProfile::simulator(2).ids});
    const busreading::BusProfile plain =
        connection::deviceBusProfile({}, 0, busreading::BusProfile::centralStation());
    EXPECT_TRUE(plain.expects(busreading::Protocol::Mcan))
        << "without devices the station's bus stays as it was";
}

// The sessions appear once the further bus is connected, and they work: the module's relays are read and
// switched, the decoder and the encoder are found and given their bus ids.
TEST(StationConnectionDevices, SessionsAreOpenedOnTheirBusAndReachTheDevices) {
    FurtherBusRig rig;
    QSignalSpy changed(&rig.connection.devices(), &ConnectionDevices::devicesChanged);
    ASSERT_TRUE(rig.start()) << rig.connection.lastProblem().toStdString();
    EXPECT_GE(changed.count(), 1);
    EXPECT_TRUE(rig.connection.buses().list()[1].profile.expects(busreading::Protocol::Orc));
    EXPECT_TRUE(rig.connection.buses().list()[0].profile.expects(busreading::Protocol::Mcan));
    ASSERT_EQ(rig.connection.devices().roModules().size(), 1u);

    ASSERT_TRUE(rig.connection.devices().roModule(QStringLiteral("RO 1"))->setOutput(3, true));
    ASSERT_TRUE(waitUntil([&] { return rig.devices.module.relay(3); }, 3000));
    rig.connection.devices().orcSession()->switchOutputs(rig.devices.decoder.busId(), 0x05);
    ASSERT_TRUE(waitUntil([&] { return rig.devices.decoder.outputs() == 0x05; }, 3000));
    EXPECT_TRUE(rig.connection.devices().refusals().isEmpty());
    EXPECT_EQ(rig.connection.buses().busFrames(0, busreading::Protocol::Ro), 0u)
        << "nothing of the devices on the station's bus";

    rig.connection.disconnectFromStation();
    EXPECT_EQ(rig.connection.devices().orcSession(), nullptr);
    EXPECT_TRUE(rig.connection.devices().roModules().empty());
}

// Notes C3: the CS2's 13-byte form has no room for an 11-bit frame.
TEST(StationConnectionDevices, AnElevenBitModuleOnATcpGatewayIsRefusedWithTheReason) {
    DeviceSettings devices;
    RoModuleSettings module = simulatorModule(1, 0);
    module.profile.ids = {0x101, 0x102, false};
    devices.roModules.push_back(module);
    StationConnection connection{support::withEmbeddedStation(settingsWith(devices))};
    QSignalSpy problems(&connection, &StationConnection::problem);
    connection.connectTo(QString());
    ASSERT_TRUE(waitUntil([&] { return connection.state() == State::Ready; }));
    ASSERT_EQ(connection.devices().refusals().size(), 1);
    const QString refusal = connection.devices().refusals().front();
    EXPECT_TRUE(refusal.contains(QStringLiteral("RO 1")) && refusal.contains(QStringLiteral("11-bit")))
        << refusal.toStdString();
    EXPECT_FALSE(problems.isEmpty());
    EXPECT_EQ(connection.devices().roModule(QStringLiteral("RO 1")), nullptr);
}

TEST(StationConnectionDevices, AModuleOnABusThatIsNotOpenIsRefused) {
    DeviceSettings devices;
    devices.roModules.push_back(simulatorModule(1, 2));
    StationConnection connection{support::withEmbeddedStation(settingsWith(devices))};
    connection.connectTo(QString());
    ASSERT_TRUE(waitUntil([&] { return connection.state() == State::Ready; }));
    ASSERT_EQ(connection.devices().refusals().size(), 1);
    EXPECT_TRUE(connection.devices().refusals().front().contains(QStringLiteral("bus 2 is not open")));
    EXPECT_TRUE(connection.devices().roModules().empty());
}

// A session that existed while its bus was away would report what it can no longer know: the sessions go
// with the bus and come anew with it, and read the devices again.
void sessionsGoAndComeBack(StationConnection& connection, SimulatedDevices& devices,
                           const std::function<void()>& unplug, const std::function<bool()>& plugIn,
                           int outageMs) {
    QSignalSpy changed(&connection.devices(), &ConnectionDevices::devicesChanged);
    unplug();
    ASSERT_TRUE(waitUntil(
        [&] { return connection.devices().roModules().empty() && !connection.devices().orcSession(); },
        5000));
    EXPECT_GE(changed.count(), 1);
    devices.module.presetRelays(0x0010); // someone switched relay 5 by hand meanwhile
    QTest::qWait(outageMs);
    EXPECT_TRUE(connection.devices().roModules().empty()) << "no session while the bus is away";
    ASSERT_TRUE(plugIn());
    ASSERT_TRUE(waitUntil([&] { return devicesWork(connection); }, ReconnectMs + ReadyMs));
    EXPECT_EQ(*connection.devices().roModule(QStringLiteral("RO 1"))->outputs(), 0x0010u)
        << "the relays are read anew";
    ASSERT_TRUE(connection.devices().roModule(QStringLiteral("RO 1"))->setOutput(1, true));
    ASSERT_TRUE(waitUntil([&] { return devices.module.relays() == 0x0011u; }, 3000));
}

class FurtherBusWithDevicesGoneFor : public ::testing::TestWithParam<int> {};

TEST_P(FurtherBusWithDevicesGoneFor, TheSessionsGoWithTheBusAndComeBackWithIt) {
    FurtherBusRig rig;
    ASSERT_TRUE(rig.start());
    sessionsGoAndComeBack(
        rig.connection, rig.devices, [&] { rig.gateway.stop(); }, [&] { return rig.gateway.listen(); },
        GetParam());
    EXPECT_EQ(rig.connection.state(), State::Ready) << "the station was not disturbed";
}

// The station's bus with the simulated CS2 and the devices on it, behind the station's TCP server.
struct StationBusRig {
    StationBusRig() : station(sim::StationLayout::demo()), connection(settingsWith(devicesOn(0))) {
        bus.attach(station);
        devices.attachTo(bus);
    }
    bool listen() {
        sim::StationServerSettings settings;
        settings.listenAddress = QHostAddress::LocalHost;
        settings.udp = false;
        settings.tcpPort = port;
        server = std::make_unique<sim::StationServer>(station, bus, settings);
        if (!server->listen())
            return false;
        port = server->tcpPort();
        return true;
    }
    sim::SimulatedBus bus;
    sim::SimulatedStation station;
    SimulatedDevices devices;
    std::unique_ptr<sim::StationServer> server;
    std::uint16_t port = 0;
    StationConnection connection;
};

class StationBusWithDevicesGoneFor : public ::testing::TestWithParam<int> {};

TEST_P(StationBusWithDevicesGoneFor, TheSessionsGoWithTheStationAndComeBackWithIt) {
    StationBusRig rig;
    ASSERT_TRUE(rig.listen());
    rig.connection.connectTo(QStringLiteral("tcp://127.0.0.1:%1").arg(rig.port));
    ASSERT_TRUE(waitUntil([&] {
        return rig.connection.state() == State::Ready && devicesWork(rig.connection);
    })) << rig.connection.lastProblem().toStdString();
    EXPECT_TRUE(rig.connection.buses().list()[0].profile.expects(busreading::Protocol::Orc));
    sessionsGoAndComeBack(
        rig.connection, rig.devices, [&] { rig.server.reset(); }, [&] { return rig.listen(); }, GetParam());
    EXPECT_TRUE(waitUntil([&] { return rig.connection.state() == State::Ready; }));
}

INSTANTIATE_TEST_SUITE_P(BackAfter, FurtherBusWithDevicesGoneFor, ::testing::Values(1000, 20000),
                         [](const auto& info) { return std::to_string(info.param / 1000) + "s"; });
INSTANTIATE_TEST_SUITE_P(BackAfter, StationBusWithDevicesGoneFor, ::testing::Values(1000, 20000),
                         [](const auto& info) { return std::to_string(info.param / 1000) + "s"; });

} // namespace
