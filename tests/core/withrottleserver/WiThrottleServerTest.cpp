// Issue 35: the WiThrottle server over real loopback sockets, in front of a railway on the simulated CS2,
// with a WiThrottle client of the tests' own: the lines of a new connection, acquire and drive confirmed by
// the station, function labels and momentary keys, steal, heartbeat and disconnect stopping the loco, the
// station unheard, garbage, flooding, turnouts and track power.

#include "withrottleserver/WiThrottleServer.h"

#include "ModelBench.h"
#include "WiThrottleTestClient.h"
#include "model/Z21Addresses.h"

namespace stellwerk::withrottleserver::test {
namespace {

using model::test::Br86;
using model::test::ModelBench;
using model::test::V100;
using model::test::waitFor;
using namespace withrottle;

const LocoAddress V100Address{3, false};   // DCC: its own address, short
const LocoAddress Br86Address{1000, true}; // mfx: the Z21 address book's first, long

AcquireLoco acquireV100(char throttle = 'T', bool steal = false) {
    return AcquireLoco{throttle, "S3", V100Address, steal};
}
ThrottleAction action(const std::string& key, LocoAction what, char throttle = 'T') {
    return ThrottleAction{throttle, key, what};
}

class WiThrottleServerTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(bench.start());
        options.address = QHostAddress::LocalHost;
        options.port = 0;
        restart();
    }

    void restart() {
        server = std::make_unique<WiThrottleServer>(addresses, options);
        QObject::connect(server.get(), &WiThrottleServer::event, server.get(),
                         [this](const WiThrottleEvent& e) { events.push_back(e); });
        ASSERT_TRUE(server->listen()) << server->errorString().toStdString();
        server->setRailway(&bench.railway);
    }

    std::unique_ptr<WiThrottleTestClient> client(const std::string& name = "phone") {
        auto made = std::make_unique<WiThrottleTestClient>(server->port());
        EXPECT_TRUE(made->waitFor<HeartbeatInterval>()) << "the greeting ends with the heartbeat";
        made->send(DeviceName{name});
        made->send(HardwareId{name + "-id"});
        return made;
    }

    // Acquires V 100 on the client's throttle T and waits until it is added.
    void acquire(WiThrottleTestClient& phone, bool steal = false) {
        phone.send(acquireV100('T', steal));
        ASSERT_TRUE(phone.waitForText("MT+S3<;>"));
    }

    int stationSpeed(std::uint32_t loco) const { return bench.station.loco(loco)->speed; }
    bool has(WiThrottleEvent::Kind kind) const {
        return std::any_of(events.begin(), events.end(),
                           [&](const WiThrottleEvent& e) { return e.kind == kind; });
    }

    ModelBench bench;
    model::Z21Addresses addresses;
    WiThrottleServerOptions options;
    std::unique_ptr<WiThrottleServer> server;
    std::vector<WiThrottleEvent> events;
};

TEST_F(WiThrottleServerTest, ANewConnectionIsSentVersionRosterPowerTurnoutsRoutesAndHeartbeat) {
    auto phone = client();
    ASSERT_FALSE(phone->texts.empty());
    EXPECT_EQ(phone->texts.front(), "VN2.0");
    const auto roster = phone->last<RosterList>();
    ASSERT_TRUE(roster.has_value());
    EXPECT_NE(std::find(roster->entries.begin(), roster->entries.end(), RosterEntry{"BR 86", Br86Address}),
              roster->entries.end());
    EXPECT_NE(std::find(roster->entries.begin(), roster->entries.end(), RosterEntry{"V 100", V100Address}),
              roster->entries.end());
    EXPECT_TRUE(phone->last<PowerStatus>().has_value());
    const auto turnouts = phone->last<TurnoutList>();
    ASSERT_TRUE(turnouts.has_value());
    ASSERT_EQ(turnouts->turnouts.size(), 2U) << "W1 and S5; the three-way W2 has no thrown/closed";
    EXPECT_EQ(turnouts->turnouts[0].systemName, "MT1");
    EXPECT_EQ(turnouts->turnouts[0].userName, "W1");
    EXPECT_EQ(turnouts->turnouts[1].systemName, "MT5");
    const auto routes = phone->last<RouteList>();
    ASSERT_TRUE(routes.has_value());
    ASSERT_EQ(routes->routes.size(), 4U);
    EXPECT_EQ(routes->routes[0].systemName, "MR1");
    EXPECT_EQ(routes->routes[0].userName, "Einfahrt");
    EXPECT_EQ(phone->last<HeartbeatInterval>()->seconds, 10);
    ASSERT_TRUE(waitFor([&] { return phone->all<HeartbeatInterval>().size() == 2; }))
        << "N is answered with *";
    EXPECT_TRUE(has(WiThrottleEvent::Kind::Joined));
    EXPECT_TRUE(has(WiThrottleEvent::Kind::Named));
}

TEST_F(WiThrottleServerTest, AnAcquiredLocosSpeedIsConfirmedByTheStationAndTold) {
    auto phone = client();
    acquire(*phone);
    phone->send(action("S3", SetSpeed{63}));
    ASSERT_TRUE(waitFor([&] { return stationSpeed(V100) == WiThrottleRailway::systemSpeed(63); }));
    ASSERT_TRUE(waitFor([&] { return phone->speedOf("S3") == 63; })) << "told the confirmed speed";
    phone->send(action("S3", SetDirection{false}));
    ASSERT_TRUE(phone->waitForText("MTAS3<;>R0"));
    EXPECT_EQ(bench.railway.throttlePort().owners().driverOf(V100), events.front().client);
    phone->send(action("*", Idle{}));
    ASSERT_TRUE(waitFor([&] { return stationSpeed(V100) == 0; }));
}

TEST_F(WiThrottleServerTest, ARosterEntryIsAcquiredWithTheLabelsOfItsFunctionsAndMomentaryKeys) {
    auto phone = client();
    phone->send(AcquireLoco{'T', "L1000", RosterSelection{"BR 86"}, false});
    ASSERT_TRUE(phone->waitFor<FunctionLabels>());
    const FunctionLabels labels = *phone->last<FunctionLabels>();
    EXPECT_EQ(labels.key, "L1000");
    ASSERT_EQ(labels.labels.size(), 32U);
    EXPECT_EQ(labels.labels[0], "F0");
    EXPECT_EQ(labels.labels[1], "F1");
    EXPECT_EQ(labels.labels[2], "") << "BR 86 has no F2: the phone hides the key";
    // F1 (sound) is momentary: on while pressed. F0 (light) latches: a press changes it, a release not.
    phone->send(action("L1000", FunctionKey{1, true, false}));
    ASSERT_TRUE(waitFor([&] { return bench.station.loco(Br86)->functions[1] != 0; }));
    phone->send(action("L1000", FunctionKey{1, false, false}));
    ASSERT_TRUE(waitFor([&] { return bench.station.loco(Br86)->functions[1] == 0; }));
    phone->send(action("L1000", FunctionKey{0, true, false}));
    phone->send(action("L1000", FunctionKey{0, false, false}));
    ASSERT_TRUE(waitFor([&] { return phone->functionOf("L1000", 0) == true; }));
    QTest::qWait(100);
    EXPECT_NE(bench.station.loco(Br86)->functions[0], 0) << "the release of a latching key changes nothing";
}

TEST_F(WiThrottleServerTest, ALocoAnotherThrottleDrivesMustBeStolenAndTheOneBeforeIsTold) {
    bench.railway.throttlePort().setSpeed(QStringLiteral("z21 127.0.0.1:61234"), V100, 300);
    auto phone = client();
    phone->send(acquireV100());
    ASSERT_TRUE(phone->waitForText("MTSS3<;>S3")) << "steal needed";
    EXPECT_TRUE(has(WiThrottleEvent::Kind::StealNeeded));
    acquire(*phone, true);
    const QString phoneName = bench.railway.throttlePort().owners().driverOf(V100);
    EXPECT_TRUE(phoneName.startsWith(QStringLiteral("withrottle ")));

    auto other = client("other");
    other->send(acquireV100('T', true));
    ASSERT_TRUE(other->waitForText("MT+S3<;>"));
    ASSERT_TRUE(phone->waitForText("MT-S3<;>")) << "the first phone lost it";
    EXPECT_TRUE(phone->waitFor<ServerMessage>());
    EXPECT_TRUE(has(WiThrottleEvent::Kind::TakenOver));
    phone->send(action("S3", SetSpeed{100}));
    other->send(action("S3", SetSpeed{20}));
    ASSERT_TRUE(waitFor([&] { return stationSpeed(V100) == WiThrottleRailway::systemSpeed(20); }));
    QTest::qWait(100);
    EXPECT_EQ(stationSpeed(V100), WiThrottleRailway::systemSpeed(20)) << "the loser no longer drives it";
}

TEST_F(WiThrottleServerTest, AClientSilentPastItsHeartbeatHasItsLocoStopped) {
    options.heartbeat = 300ms;
    options.grace = 100ms;
    restart();
    auto phone = client();
    EXPECT_EQ(phone->last<HeartbeatInterval>()->seconds, 1);
    acquire(*phone);
    phone->send(action("S3", SetSpeed{80}));
    ASSERT_TRUE(waitFor([&] { return stationSpeed(V100) > 0; }));
    ASSERT_TRUE(waitFor([&] { return server->clientCount() == 0; }));
    EXPECT_TRUE(has(WiThrottleEvent::Kind::TimedOut));
    ASSERT_TRUE(waitFor([&] { return stationSpeed(V100) == 0; })) << "the station confirms speed 0";
    EXPECT_TRUE(bench.railway.throttlePort().owners().driverOf(V100).isEmpty());
}

TEST_F(WiThrottleServerTest, AClientThatKeepsItsHeartbeatStays) {
    options.heartbeat = 300ms;
    options.grace = 100ms;
    restart();
    auto phone = client();
    for (int beat = 0; beat < 8; ++beat) {
        phone->send(Heartbeat{});
        QTest::qWait(100);
    }
    EXPECT_EQ(server->clientCount(), 1U);
    EXPECT_FALSE(has(WiThrottleEvent::Kind::TimedOut));
}

TEST_F(WiThrottleServerTest, AClientDroppedByTheOperatorIsClosedAndItsLocoStopped) {
    auto phone = client();
    acquire(*phone);
    phone->send(action("S3", SetSpeed{80}));
    ASSERT_TRUE(waitFor([&] { return stationSpeed(V100) > 0; }));
    ASSERT_EQ(server->clientCount(), 1U);
    const WiThrottleClient& known = server->clients().front();
    EXPECT_EQ(known.lastLine, QStringLiteral("MTAS3<;>V80"));
    EXPECT_TRUE(known.lastLineAt.isValid());
    const QString name = known.name();
    EXPECT_FALSE(server->dropClient(QStringLiteral("withrottle 127.0.0.1:1"))) << "nobody by that name";
    EXPECT_TRUE(server->dropClient(name));
    EXPECT_EQ(server->clientCount(), 0U);
    ASSERT_TRUE(waitFor([&] { return stationSpeed(V100) == 0; }));
    ASSERT_TRUE(waitFor([&] { return !phone->connected(); })) << "the connection is closed";
    EXPECT_TRUE(has(WiThrottleEvent::Kind::Dropped));
}

TEST_F(WiThrottleServerTest, ADisconnectStopsTheLoco) {
    auto phone = client();
    acquire(*phone);
    phone->send(action("S3", SetSpeed{80}));
    ASSERT_TRUE(waitFor([&] { return stationSpeed(V100) > 0; }));
    phone->close();
    ASSERT_TRUE(waitFor([&] { return stationSpeed(V100) == 0; }));
    EXPECT_TRUE(has(WiThrottleEvent::Kind::Left));
    ASSERT_TRUE(waitFor([&] { return server->clientCount() == 0; }));
}

TEST_F(WiThrottleServerTest, QuitStopsTheLocoAndCloses) {
    auto phone = client();
    acquire(*phone);
    phone->send(action("S3", SetSpeed{80}));
    ASSERT_TRUE(waitFor([&] { return stationSpeed(V100) > 0; }));
    phone->send(Quit{});
    ASSERT_TRUE(waitFor([&] { return stationSpeed(V100) == 0; }));
    EXPECT_TRUE(has(WiThrottleEvent::Kind::Quit));
    ASSERT_TRUE(waitFor([&] { return !phone->connected(); }));
}

TEST_F(WiThrottleServerTest, WhileTheStationIsNotHeardCommandsAreRefusedAndNeverReplayed) {
    auto phone = client();
    acquire(*phone);
    bench.stall();
    bench.stationEnd.close();
    ASSERT_FALSE(bench.railway.isStateReported());
    ASSERT_TRUE(phone->waitForText("PPA2")) << "the power is shown unknown";
    phone->send(action("S3", SetSpeed{90}));
    phone->send(SwitchTurnout{TurnoutAction::Throw, "MT1"});
    ASSERT_TRUE(waitFor([&] { return server->counters().refused == 2; }));
    ASSERT_TRUE(phone->waitFor<ServerMessage>());
    EXPECT_TRUE(has(WiThrottleEvent::Kind::Refused));
    bench.stationEnd.open();
    bench.wake();
    QTest::qWait(200);
    EXPECT_EQ(stationSpeed(V100), 0) << "nothing refused is sent later";
}

TEST_F(WiThrottleServerTest, GarbageAndOverlongLinesAreCountedAndTheClientStillServed) {
    auto phone = client();
    phone->sendText("garbage\n\x01\x02\x03\nMTA\n");
    phone->sendText(std::string(5000, 'x') + "\n");
    acquire(*phone);
    EXPECT_EQ(server->counters().unknownLines, 3U);
    EXPECT_EQ(server->counters().overlongLines, 1U);
    EXPECT_EQ(server->clientCount(), 1U);
}

TEST_F(WiThrottleServerTest, AFloodingClientIsLimitedAndAnotherIsStillServed) {
    options.linesPerSecond = 50;
    restart();
    auto calm = client("calm");
    auto flood = client("flood");
    std::string burst;
    for (int i = 0; i < 1000; ++i)
        burst += "*\n";
    flood->sendText(burst);
    acquire(*calm);
    ASSERT_TRUE(waitFor([&] { return server->counters().limited > 0; }));
    EXPECT_TRUE(has(WiThrottleEvent::Kind::Flooding));
    EXPECT_EQ(server->clientCount(), 2U);
}

TEST_F(WiThrottleServerTest, ATurnoutThrowReachesTheStationAndEveryClientIsTold) {
    auto phone = client();
    auto watcher = client("watcher");
    phone->send(SwitchTurnout{TurnoutAction::Close, "MT1"});
    ASSERT_TRUE(waitFor([&] {
        return bench.railway.accessory(1)->isPositionReported() &&
               bench.railway.accessory(1)->position() == 1;
    }));
    ASSERT_TRUE(watcher->waitForText("PTA2MT1")) << "closed, told to every client";
    phone->send(SwitchTurnout{TurnoutAction::Toggle, "MT1"});
    ASSERT_TRUE(waitFor([&] { return bench.railway.accessory(1)->position() == 0; }));
    ASSERT_TRUE(watcher->waitForText("PTA4MT1")) << "thrown";
    phone->send(SwitchTurnout{TurnoutAction::Throw, "MT2"});
    ASSERT_TRUE(phone->waitForText("HMNo turnout MT2"));
}

TEST_F(WiThrottleServerTest, TrackPowerOffReachesTheStationAndEveryClientIsTold) {
    auto phone = client();
    auto watcher = client("watcher");
    phone->send(SetPower{false});
    ASSERT_TRUE(waitFor([&] { return bench.railway.power() == station::PowerState::Stopped; }));
    ASSERT_TRUE(watcher->waitForText("PPA0"));
}

TEST_F(WiThrottleServerTest, ARouteIsSetFromItsSystemName) {
    auto phone = client();
    phone->send(SetRoute{"MR1"});
    ASSERT_TRUE(waitFor([&] { return bench.railway.accessory(1)->position() == 1; }))
        << "Einfahrt sets W1 straight";
}

TEST_F(WiThrottleServerTest, SpeedStepsMapOntoTheStationsRange) {
    EXPECT_EQ(WiThrottleRailway::systemSpeed(0), 0);
    EXPECT_EQ(WiThrottleRailway::systemSpeed(126), 1000);
    EXPECT_EQ(WiThrottleRailway::systemSpeed(63), 500);
    EXPECT_EQ(WiThrottleRailway::throttleSpeed(500), 63);
    EXPECT_EQ(WiThrottleRailway::throttleSpeed(1000), 126);
}

TEST_F(WiThrottleServerTest, AConnectionFromAnAddressNotAllowedIsClosedAtOnce) {
    options.allowedClients = {QHostAddress(QStringLiteral("127.0.0.2"))};
    restart();
    WiThrottleTestClient stranger(server->port()); // connects from 127.0.0.1
    ASSERT_TRUE(waitFor([&] { return server->counters().notAllowed == 1; }));
    EXPECT_TRUE(waitFor([&] { return !stranger.connected(); }));
    EXPECT_EQ(server->clientCount(), 0U);
    EXPECT_FALSE(has(WiThrottleEvent::Kind::Joined));

    options.allowedClients = {QHostAddress::LocalHost};
    restart();
    auto phone = client();
    EXPECT_TRUE(phone->connected());
    EXPECT_EQ(server->clientCount(), 1U);
    EXPECT_EQ(server->counters().notAllowed, 0U);
}

} // namespace
} // namespace stellwerk::withrottleserver::test
