// Issue 11, at the session's level: a command the session has given up on (or cancelled) never reaches
// the station later, over real sockets. The assertion each time is the station's received log.

#include "E2eSupport.h"
#include "LossyRelay.h"
#include "StationLog.h"

#include <QTest>

namespace stellwerk::e2e {
namespace {

using State = transport::Transport::State;
using Status = CommandResult::Status;

// Short give-up deadlines keep the tests fast: 3 attempts, 100 ms apart.
station::StationSettings impatient() {
    station::StationSettings settings = sessionSettings();
    settings.commands = {100ms, 2};
    return settings;
}

// Sends without waiting; the result arrives in `result`.
std::shared_ptr<std::optional<CommandResult>> requestSpeed(Rig& rig, std::uint32_t loco,
                                                           std::uint16_t speed) {
    auto result = std::make_shared<std::optional<CommandResult>>();
    rig.session->request(command(cs2::LocoSpeed{cs2::LocId(loco), speed}),
                         [result](const CommandResult& r) { *result = r; });
    return result;
}

// The station goes away in the middle of a speed command and is back after 1 s: the command fails at
// once, what was said while it was away is refused, and none of it reaches the station when it is back.
TEST(TcpStationGoneMidCommand, GivenUpCommandNeverReachesItWhenItIsBackAfterOneSecond) {
    Rig rig(Wire::Tcp, impatient());
    ASSERT_TRUE(rig.start());
    StationLog log(rig.station);
    const auto before = rig.station.loco(MfxLoco)->speed;

    const auto gone = requestSpeed(rig, MfxLoco, 777);
    rig.stopServer(); // before the station read it: the command is in flight
    ASSERT_TRUE(waitFor([&] { return gone->has_value(); }));
    EXPECT_FALSE(gone->value().succeeded());
    ASSERT_TRUE(waitFor([&] { return rig.transport->state() == State::Reconnecting; }));
    const auto meanwhile = requestSpeed(rig, MfxLoco, 888);
    ASSERT_TRUE(meanwhile->has_value()) << "refused at once while the station is away";
    EXPECT_EQ(meanwhile->value().status, Status::NotSent);

    QTest::qWait(1000);
    ASSERT_TRUE(rig.startServer());
    ASSERT_TRUE(waitFor([&] { return rig.transport->state() == State::Connected; }));
    QTest::qWait(500); // longer than every retry would have taken
    EXPECT_FALSE(log.received(MfxLoco, 777)) << "a failed command reached the station";
    EXPECT_FALSE(log.received(MfxLoco, 888)) << "a refused command reached the station";
    EXPECT_EQ(rig.station.loco(MfxLoco)->speed, before);
    EXPECT_EQ(rig.session->tracker().pendingCount(), 0U);
    // And the conversation goes on.
    EXPECT_TRUE(rig.acknowledge(command(cs2::LocoSpeed{cs2::LocId(MfxLoco), 100})).succeeded());
    EXPECT_EQ(log.speedsSet(MfxLoco), std::vector<std::uint16_t>{100});
}

// A station that accepts the connection but never reads: commands fail, nothing claims success, the
// connection is reset (so nothing of them is read later) and made again, and nothing piles up.
TEST(TcpPeerThatNeverReads, CommandsFailAndNothingPilesUp) {
    QTcpServer deaf;
    ASSERT_TRUE(deaf.listen(QHostAddress::LocalHost, 0));
    deaf.pauseAccepting(); // the kernel completes connections; nobody takes or reads them
    auto transport = transport::createTransport(
        transport::TcpSettings{QStringLiteral("127.0.0.1"), deaf.serverPort(), fastReconnect()});
    bus::Bus bus(*transport, busreading::BusProfile::centralStation());
    station::StationSession session(bus, impatient());
    transport->open();
    ASSERT_TRUE(waitFor([&] { return transport->state() == State::Connected; }));
    int acknowledged = 0;
    int failed = 0;
    constexpr int Commands = 2000;
    for (int i = 0; i < Commands; ++i)
        session.request(command(cs2::LocoSpeed{cs2::LocId(MfxLoco), std::uint16_t(i % 1000)}),
                        [&](const CommandResult& r) { (r.succeeded() ? acknowledged : failed) += 1; });
    ASSERT_TRUE(waitFor([&] { return acknowledged + failed == Commands; }, 3 * WaitMs));
    EXPECT_EQ(acknowledged, 0);
    EXPECT_EQ(session.tracker().pendingCount(), 0U);
    EXPECT_EQ(transport->queuedFrames(), 0U);
    EXPECT_LE(transport->counters().framesOut, std::uint64_t(Commands) * 3);
    EXPECT_TRUE(waitFor([&] { return transport->counters().reconnects >= 1; }))
        << "a given-up command to a peer that said nothing resets the connection";
}

// Every other answer of a UDP station is lost: commands still succeed through their retries, and the
// station receives each command once or as its retries, in order, and nothing else of them.
TEST(UdpStationAnsweringEveryOtherFrame, CommandsSucceedThroughRetries) {
    Rig rig(Wire::Udp);
    LossyRelay relay(rig.appUdpPort());
    ASSERT_TRUE(relay.bound());
    rig.stationRepliesTo(relay.port());
    ASSERT_TRUE(rig.start());
    StationLog log(rig.station);
    const std::vector<std::uint16_t> speeds{100, 200, 300, 400, 500, 600};
    for (const std::uint16_t speed : speeds) {
        const CommandResult result = rig.acknowledge(command(cs2::LocoSpeed{cs2::LocId(Mm2Loco), speed}));
        EXPECT_EQ(result.status, Status::Acknowledged) << station::commandStatusName(result.status);
    }
    EXPECT_GT(relay.dropped(), 0);
    EXPECT_EQ(rig.station.loco(Mm2Loco)->speed, 600);
    std::vector<std::uint16_t> distinct;
    for (const std::uint16_t speed : log.speedsSet(Mm2Loco))
        if (distinct.empty() || distinct.back() != speed)
            distinct.push_back(speed);
    EXPECT_EQ(distinct, speeds) << "each command, in order, repeated only by its own retries";
    EXPECT_LE(log.speedsSet(Mm2Loco).size(), speeds.size() * 2);
}

// A UDP station that disappears: the retries go nowhere, and nothing of the given-up command is sent
// once it is back (UDP has no connection to lose; the give-up alone must stop it).
TEST(UdpStationGoneMidCommand, GivenUpCommandNeverReachesItWhenItIsBack) {
    Rig rig(Wire::Udp, impatient());
    ASSERT_TRUE(rig.start());
    StationLog log(rig.station);
    rig.transport->setPacing(400ms); // retries wait in the queue behind the pacing (a Gleisbox gap)
    rig.stopServer();
    const auto gone = requestSpeed(rig, MfxLoco, 777);
    ASSERT_TRUE(waitFor([&] { return gone->has_value(); }));
    EXPECT_EQ(gone->value().status, Status::TimedOut);
    ASSERT_TRUE(rig.startServer());
    QTest::qWait(1000); // longer than the paced retries would have waited
    EXPECT_FALSE(log.received(MfxLoco, 777));
    EXPECT_EQ(rig.transport->queuedFrames(), 0U);
}

} // namespace
} // namespace stellwerk::e2e
