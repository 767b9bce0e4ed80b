// Issue 15 end to end: an OpenRailCAN throttle on the station's bus beside the simulated CS2 drives the CS2's
// locomotives through Stellwerk, the central there. The app holds the connection as the GUI does, with a
// railway per session and its RailwayThrottles following the central; between them real loopback sockets
// (UDP) or Qt's virtualcan bus. Asserted: what reached the simulated station (its received log) and what
// the throttle was answered. Under faults the station goes away as Stellwerk passes a throttle's speed on,
// and comes back after 1 s and after 20 s: the given-up command never reaches it, and the throttle drives
// and stops the loco again afterwards.

#include "E2eSupport.h"
#include "StationLog.h"
#include "connection/StationConnection.h"
#include "cs2/Codec.h"
#include "model/Railway.h"
#include "model/RailwayThrottles.h"
#include "sim/SimulatedBus.h"
#include "sim/SimulatedOrcDevices.h"
#include "transport/TransportAddress.h"

#include <QElapsedTimer>
#include <QTest>
#include <iostream>

namespace stellwerk::e2e {
namespace {

constexpr std::uint32_t ThrottleUid = 0x3A2E0400; // bus id 0x0400, a throttle (device type 1)

// Whether the frames carry the CS2 command that sets the locomotive's speed.
bool framesSetSpeed(const std::vector<can::CanFrame>& frames, std::uint32_t locId, std::uint16_t speed) {
    for (const can::CanFrame& frame : frames) {
        const auto message = cs2::decode(frame);
        const auto* body = message ? std::get_if<cs2::LocoSpeed>(&message->body) : nullptr;
        if (body && !message->response && body->loco.value() == locId && body->speed == speed)
            return true;
    }
    return false;
}

// How often the station received the CS2 message `T` (a command, not an answer) that `matches`.
template <typename T>
int received(const StationLog& log, const std::function<bool(const T&)>& matches) {
    int count = 0;
    for (const can::CanFrame& frame : log.frames()) {
        const auto message = cs2::decode(frame);
        const T* body = message && !message->response ? std::get_if<T>(&message->body) : nullptr;
        count += body && matches(*body) ? 1 : 0;
    }
    return count;
}

// The station's side: the simulated CS2 of the demo layout and an ORC throttle on one bus behind the
// station's server.
class ThrottleStation {
public:
    explicit ThrottleStation(Wire wire) : wire_(wire) {
        bus.attach(station);
        bus.attach(throttle);
        throttle.plugIn();
        if (wire_ == Wire::Udp)
            appUdpPort_ = freeUdpPort();
    }
    // (Re)opens the station's listeners on the ports of the last time (free ones the first time).
    bool listen() {
        sim::StationServerSettings settings;
        settings.listenAddress = QHostAddress::LocalHost;
        settings.tcp = false;
        settings.udp = wire_ == Wire::Udp;
        settings.udpPort = stationUdpPort_;
        settings.udpReplyHost = QHostAddress::LocalHost;
        settings.udpReplyPort = appUdpPort_;
        if (wire_ == Wire::VirtualCan)
            settings.canBus = virtualBus();
        server = std::make_unique<sim::StationServer>(station, bus, settings);
        if (!server->listen())
            return false;
        stationUdpPort_ = server->udpPort();
        return true;
    }
    void stopServer() { server.reset(); }
    QString url() const {
        if (wire_ == Wire::Udp)
            return QStringLiteral("udp://127.0.0.1:%1?listen=%2").arg(stationUdpPort_).arg(appUdpPort_);
        return transport::transportUrl(virtualBus());
    }

    sim::SimulatedBus bus;
    sim::SimulatedStation station{sim::StationLayout::demo()};
    sim::SimulatedOrcThrottle throttle{ThrottleUid};
    std::unique_ptr<sim::StationServer> server;

private:
    Wire wire_;
    std::uint16_t appUdpPort_ = 0;
    std::uint16_t stationUdpPort_ = 0;
};

// The app's side: the connection with the central on the station's bus, the railway made at each session
// and the throttles driving it.
class ThrottleApp {
public:
    ThrottleApp() : connection(settings()) {
        QObject::connect(&connection, &connection::StationConnection::sessionStarted, &connection,
                         [this](station::StationSession* session) {
                             railway = std::make_unique<model::Railway>(*session);
                             throttles = new model::RailwayThrottles(*railway, railway.get());
                             follow();
                         });
        QObject::connect(&connection, &connection::StationConnection::configurationLoaded, &connection,
                         [this](const station::StartupResult& result) { railway->load(result); });
        QObject::connect(&connection.devices(), &connection::ConnectionDevices::devicesChanged, &connection,
                         [this] { follow(); });
    }
    void follow() {
        if (railway)
            throttles->setSession(connection.devices().orcSession());
    }
    // Ready, the railway loaded and a bridge beside the central.
    bool ready(int timeoutMs = 3 * WaitMs) {
        return waitFor(
            [this] {
                return connection.state() == connection::StationConnection::State::Ready && railway &&
                       railway->isStateReported() && throttles->bridge();
            },
            timeoutMs);
    }

    connection::StationConnection connection;
    std::unique_ptr<model::Railway> railway;
    model::RailwayThrottles* throttles = nullptr; // a child of the railway

private:
    static connection::ConnectionSettings settings() {
        connection::ConnectionSettings settings;
        settings.session = sessionSettings();
        settings.session.commands = {100ms, 2};
        settings.session.liveness = {200ms, 3};
        settings.startup.deviceWindow = 100ms;
        settings.startup.readStatusData = false;
        settings.devices.orc.on = true;
        settings.devices.orc.bus = 0;
        return settings;
    }
};

class ThrottlesOverWire : public ::testing::TestWithParam<Wire> {};

// Lok Speed for the demo's mfx loco (Ziel-Id 0x4001) reaches the CS2 as its speed; the speed query is
// answered from it; Lok(s) Nothalt for all is the station's STOP.
TEST_P(ThrottlesOverWire, AThrottleDrivesAndStopsTheCs2sLoco) {
    ThrottleStation station(GetParam());
    ASSERT_TRUE(station.listen());
    StationLog log(station.station);
    ThrottleApp app;
    app.connection.connectTo(station.url());
    ASSERT_TRUE(app.ready()) << app.connection.lastProblem().toStdString();

    QElapsedTimer clock;
    clock.start();
    station.throttle.drive(MfxLoco, 300);
    ASSERT_TRUE(waitFor([&] { return station.station.loco(MfxLoco)->speed == 300; }));
    // A figure for the record: the throttle's frame to Stellwerk and its CS2 command back to the station.
    std::cout << "throttle to station over " << wireName(GetParam()) << ": " << clock.nsecsElapsed() / 1000
              << " us" << std::endl;
    EXPECT_EQ(log.speedsSet(MfxLoco), std::vector<std::uint16_t>{300});
    ASSERT_TRUE(waitFor([&] { return app.railway->locomotive(MfxLoco)->speed() == 300; }));
    station.throttle.querySpeed(MfxLoco);
    ASSERT_TRUE(waitFor([&] { return station.throttle.answeredSpeed(MfxLoco).has_value(); }));
    EXPECT_EQ(*station.throttle.answeredSpeed(MfxLoco), 300);

    station.throttle.emergencyStop();
    ASSERT_TRUE(
        waitFor([&] { return received<cs2::SystemStop>(log, [](const auto&) { return true; }) == 1; }));
}

INSTANTIATE_TEST_SUITE_P(Wires, ThrottlesOverWire, ::testing::Values(Wire::Udp, Wire::VirtualCan),
                         [](const auto& info) { return wireName(info.param); });

class ThrottleStationGoneMidCommand : public ::testing::TestWithParam<int> {};

TEST_P(ThrottleStationGoneMidCommand, TheGivenUpSpeedNeverArrivesAndTheThrottleDrivesAgain) {
    const int outageMs = GetParam();
    ThrottleStation station(Wire::Udp);
    ASSERT_TRUE(station.listen());
    StationLog log(station.station);
    ThrottleApp app;
    app.connection.connectTo(station.url());
    ASSERT_TRUE(app.ready());
    QObject::connect(&app.connection.buses(), &connection::ConnectionBuses::stationFramesSeen,
                     &app.connection, [&](const std::vector<can::CanFrame>& frames, bool outgoing) {
                         if (outgoing && station.server && framesSetSpeed(frames, MfxLoco, 777))
                             station.stopServer(); // the station goes with the command on its way
                     });

    station.throttle.drive(MfxLoco, 777);
    ASSERT_TRUE(waitFor([&] { return !station.server; })) << "Stellwerk passed the speed on";
    ASSERT_TRUE(waitFor([&] { return !app.railway->isStateReported(); }));
    station.throttle.drive(MfxLoco, 888); // while the station is gone

    QTest::qWait(outageMs);
    ASSERT_TRUE(station.listen());
    ASSERT_TRUE(app.ready(outageMs + 4 * WaitMs));
    QTest::qWait(300);
    EXPECT_FALSE(log.received(MfxLoco, 777)) << "a given-up command reached the station";
    EXPECT_FALSE(log.received(MfxLoco, 888)) << "a command of the outage reached the station";
    EXPECT_EQ(station.station.loco(MfxLoco)->speed, 0);

    station.throttle.drive(MfxLoco, 100);
    ASSERT_TRUE(waitFor([&] { return log.received(MfxLoco, 100); })) << "and drives again";
    station.throttle.emergencyStop(MfxLoco);
    ASSERT_TRUE(waitFor([&] {
        return received<cs2::LocoEmergencyStop>(
                   log, [](const cs2::LocoEmergencyStop& s) { return s.loco.value() == MfxLoco; }) == 1;
    })) << "the e-stop goes through";
}

// 1 s: back before any retry gives up. 20 s: past every retry and give-up deadline.
INSTANTIATE_TEST_SUITE_P(BackAfter, ThrottleStationGoneMidCommand, ::testing::Values(1000, 20000),
                         [](const auto& info) { return std::to_string(info.param / 1000) + "s"; });

} // namespace
} // namespace stellwerk::e2e
