// Issue 11, as the app holds it: StationConnection and Railway against the simulated CS2 over TCP.
// A station that disappears mid-command and comes back: nothing given up is ever received, nothing is
// shown as done that the station did not confirm, the state is "not reported" while the station is
// away and is read again after it is back; the track power stays unknown until the station reports it.

#include "E2eSupport.h"
#include "EmbeddedStationSupport.h"
#include "StationLog.h"
#include "connection/StationConnection.h"
#include "cs2/Codec.h"
#include "model/Railway.h"

#include <QSignalSpy>
#include <QTest>

namespace stellwerk::e2e {
namespace {

using connection::StationConnection;
using model::Railway;
using station::PowerState;

// Another controller on the station's bus (an MS2) while we are away or alongside us.
void otherController(sim::SimulatedStation& station, cs2::MessageBody body) {
    station.receive(cs2::encode(cs2::Message{0, false, 0x2F11, std::move(body)}));
}

connection::ConnectionSettings fastConnection() {
    connection::ConnectionSettings settings;
    settings.session.uid = 0x53574B02;
    settings.session.commands = {100ms, 2};
    settings.session.liveness = {200ms, 3};
    settings.startup.deviceWindow = 100ms;
    settings.startup.readStatusData = false;
    return settings;
}

// The app's side: the connection, and a railway made and loaded as the app does it.
class App {
public:
    App() {
        QObject::connect(&connection, &StationConnection::sessionStarted, &connection,
                         [this](station::StationSession* session) {
                             railway = std::make_unique<Railway>(*session);
                             QObject::connect(railway.get(), &Railway::powerChanged, railway.get(),
                                              [this](PowerState state) { powers.push_back(state); });
                         });
        QObject::connect(&connection, &StationConnection::configurationLoaded, &connection,
                         [this](const station::StartupResult& result) { railway->load(result); });
    }

    bool ready(int timeoutMs = 3 * WaitMs) {
        return waitFor(
            [&] {
                return connection.state() == StationConnection::State::Ready && railway &&
                       railway->isStateReported();
            },
            timeoutMs);
    }

    const model::Locomotive& loco(std::uint32_t id) const { return *railway->locomotive(id); }

    StationConnection connection{support::withEmbeddedStation(fastConnection())};
    std::unique_ptr<Railway> railway;
    std::vector<PowerState> powers;
};

class StationGoneMidCommand : public ::testing::TestWithParam<int> {};

TEST_P(StationGoneMidCommand, NothingGivenUpArrivesAndTheStateIsReadAgain) {
    const int outageMs = GetParam();
    Rig rig(Wire::Tcp);
    ASSERT_TRUE(rig.startServer());
    StationLog log(rig.station);
    App app;
    app.connection.connectTo(QStringLiteral("tcp://127.0.0.1:%1").arg(rig.stationTcpPort()));
    ASSERT_TRUE(app.ready());
    otherController(rig.station, cs2::LocoSpeed{cs2::LocId(MfxLoco), 300});
    otherController(rig.station, cs2::SystemGo{0});
    ASSERT_TRUE(waitFor([&] { return app.loco(MfxLoco).speed() == 300 && app.railway->power(); }));
    QSignalSpy failed(app.railway.get(), &Railway::locomotiveCommandFailed);
    QSignalSpy acknowledged(app.railway.get(), &Railway::locomotiveCommandAcknowledged);

    app.railway->setSpeed(MfxLoco, 777);
    rig.stopServer(); // the station disappears with the command in flight
    ASSERT_TRUE(waitFor([&] { return failed.count() == 1; }));
    EXPECT_FALSE(app.railway->isStateReported());
    EXPECT_FALSE(app.loco(MfxLoco).isSpeedReported());
    EXPECT_EQ(app.loco(MfxLoco).speed(), 300) << "the failed value is not shown";
    EXPECT_FALSE(app.railway->power().has_value()) << "power is unknown while the station is away";
    app.railway->setSpeed(MfxLoco, 888); // while it is away
    EXPECT_EQ(failed.count(), 2) << "refused at once";
    // Meanwhile at the station: another controller drives on and switches the power off.
    otherController(rig.station, cs2::LocoSpeed{cs2::LocId(MfxLoco), 450});
    otherController(rig.station, cs2::SystemStop{0});

    QTest::qWait(outageMs);
    ASSERT_TRUE(rig.startServer());
    ASSERT_TRUE(app.ready(outageMs + 4 * WaitMs));
    EXPECT_FALSE(log.received(MfxLoco, 777)) << "a given-up command reached the station";
    EXPECT_FALSE(log.received(MfxLoco, 888)) << "a refused command reached the station";
    EXPECT_EQ(acknowledged.count(), 0);
    EXPECT_EQ(rig.station.loco(MfxLoco)->speed, 450);
    EXPECT_EQ(app.loco(MfxLoco).speed(), 450) << "read again from the station";
    EXPECT_TRUE(app.loco(MfxLoco).isSpeedReported());
    EXPECT_FALSE(app.railway->power().has_value()) << "the CS2 has no power query: unknown until reported";
    otherController(rig.station, cs2::SystemStop{0}); // the station reports it
    ASSERT_TRUE(waitFor([&] { return app.railway->power().has_value(); }));
    EXPECT_EQ(*app.railway->power(), PowerState::Stopped);
}

// 1 s: back before the reconnect back-off grows. 20 s: well past every retry and give-up deadline.
INSTANTIATE_TEST_SUITE_P(BackAfter, StationGoneMidCommand, ::testing::Values(1000, 20000),
                         [](const auto& info) { return std::to_string(info.param / 1000) + "s"; });

// The station's power was switched off while we were away; it announces its power to a new client.
TEST(StationWhosePowerWasTurnedOffMeanwhile, IsNotShownWithPowerOn) {
    Rig rig(Wire::Tcp);
    rig.announcePower = true;
    ASSERT_TRUE(rig.startServer());
    App app;
    app.connection.connectTo(QStringLiteral("tcp://127.0.0.1:%1").arg(rig.stationTcpPort()));
    ASSERT_TRUE(app.ready());
    otherController(rig.station, cs2::SystemGo{0});
    ASSERT_TRUE(waitFor([&] { return app.railway->power() == PowerState::Running; }));

    rig.stopServer();
    ASSERT_TRUE(waitFor([&] { return !app.railway->isStateReported(); }));
    EXPECT_FALSE(app.railway->power().has_value());
    otherController(rig.station, cs2::SystemStop{0});
    app.powers.clear();
    ASSERT_TRUE(rig.startServer());
    ASSERT_TRUE(app.ready());
    ASSERT_TRUE(waitFor([&] { return app.railway->power().has_value(); }));
    EXPECT_EQ(*app.railway->power(), PowerState::Stopped);
    EXPECT_EQ(app.powers, std::vector{PowerState::Stopped});
    EXPECT_EQ(rig.station.power(), sim::SimulatedStation::Power::Stopped);
}

// The embedded station tells a new controller its power and never switches it on for them.
TEST(EmbeddedStation, NewControllerDoesNotSwitchThePowerOn) {
    App app;
    app.connection.connectToSimulator();
    ASSERT_TRUE(app.ready());
    ASSERT_TRUE(waitFor([&] { return app.railway->power() == PowerState::Running; })) << "announced";
    auto other = transport::createTransport(
        transport::TcpSettings{QStringLiteral("127.0.0.1"), app.connection.embeddedPort(), fastReconnect()});
    other->open();
    ASSERT_TRUE(waitFor([&] { return other->state() == transport::Transport::State::Connected; }));
    other->send(cs2::encode(cs2::Message{0, false, 0x2F11, cs2::SystemStop{0}}));
    ASSERT_TRUE(waitFor([&] { return app.railway->power() == PowerState::Stopped; }));
    app.powers.clear();
    auto another = transport::createTransport(
        transport::TcpSettings{QStringLiteral("127.0.0.1"), app.connection.embeddedPort(), fastReconnect()});
    another->open();
    ASSERT_TRUE(waitFor([&] { return another->state() == transport::Transport::State::Connected; }));
    QTest::qWait(300);
    EXPECT_EQ(app.railway->power(), PowerState::Stopped);
    for (const PowerState state : app.powers)
        EXPECT_NE(state, PowerState::Running) << "the power was switched on for a new controller";
}

} // namespace
} // namespace stellwerk::e2e
