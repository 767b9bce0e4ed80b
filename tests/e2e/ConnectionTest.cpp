// Losing the station and getting it back: a TCP station that restarts is reconnected and the session
// catches up with its state; a UDP station that falls silent is reported, and reported back.
//
// The session itself does not resynchronise on reconnect: the transport reconnects, commands are
// acknowledged again at once, and running the start-up again (its state queries) brings the app's view
// back to the station's. These tests show exactly that.

#include "E2eSupport.h"
#include "cs2/Codec.h"
#include "station/StartupSequence.h"

#include <QElapsedTimer>
#include <QSignalSpy>

namespace stellwerk::e2e {
namespace {

using State = transport::Transport::State;
using Status = CommandResult::Status;

// Another controller on the station's bus (an MS2) sets a loco's speed while we are away.
void otherControllerSetsSpeed(sim::SimulatedStation& station, std::uint32_t locId, std::uint16_t speed) {
    station.receive(cs2::encode(cs2::Message{0, false, 0x2F11, cs2::LocoSpeed{cs2::LocId(locId), speed}}));
}

// The speeds the start-up's state queries reported, by Loc-ID.
std::map<std::uint32_t, std::uint16_t> speedsAfterStartup(station::StationSession& session) {
    std::map<std::uint32_t, std::uint16_t> speeds;
    QObject context;
    QObject::connect(&session, &station::StationSession::updated, &context,
                     [&](const station::StationUpdates& updates) {
                         for (const auto& change : updates.speeds)
                             speeds[change.loco.value()] = change.speed;
                     });
    station::StartupSequence startup(session, {.deviceWindow = 200ms, .readStatusData = false});
    bool ready = false;
    QObject::connect(&startup, &station::StartupSequence::ready, &context, [&] { ready = true; });
    startup.start();
    EXPECT_TRUE(waitFor([&] { return ready; }, 3 * WaitMs));
    return speeds;
}

TEST(TcpStation, ThatRestartsIsReconnectedAndResynchronised) {
    Rig rig(Wire::Tcp);
    ASSERT_TRUE(rig.start());
    ASSERT_TRUE(rig.acknowledge(command(cs2::LocoSpeed{cs2::LocId(MfxLoco), 400})).succeeded());
    QSignalSpy problems(rig.transport.get(), &transport::Transport::problem);

    rig.stopServer(); // the station goes away with its connections
    ASSERT_TRUE(waitFor([&] { return rig.transport->state() == State::Reconnecting; }));
    EXPECT_GE(problems.count(), 1);
    otherControllerSetsSpeed(rig.station, MfxLoco, 720);
    ASSERT_TRUE(rig.startServer()); // back on the same port

    ASSERT_TRUE(waitFor([&] { return rig.transport->state() == State::Connected; }));
    EXPECT_EQ(rig.transport->counters().reconnects, 1U);
    // Commands are acknowledged again, and queries answer what the station has now.
    const CommandResult speed = rig.acknowledge(command(cs2::LocoSpeed{cs2::LocId(Mm2Loco), 300}));
    EXPECT_EQ(speed.status, Status::Acknowledged) << station::commandStatusName(speed.status);
    EXPECT_EQ(rig.station.loco(Mm2Loco)->speed, 300);
    const CommandResult query = rig.acknowledge(command(cs2::LocoSpeed{cs2::LocId(MfxLoco), std::nullopt}));
    ASSERT_TRUE(query.succeeded());
    EXPECT_EQ(std::get<cs2::LocoSpeed>(query.answer->body).speed, 720);
    // The start-up run again reports every loco's speed as the station has it.
    const auto speeds = speedsAfterStartup(*rig.session);
    EXPECT_EQ(speeds.at(MfxLoco), 720);
    EXPECT_EQ(speeds.at(Mm2Loco), 300);
}

TEST(TcpStation, ThatRestartsTwiceIsReconnectedTwice) {
    Rig rig(Wire::Tcp);
    ASSERT_TRUE(rig.start());
    for (std::uint64_t restart = 1; restart <= 2; ++restart) {
        rig.stopServer();
        ASSERT_TRUE(waitFor([&] { return rig.transport->state() == State::Reconnecting; }));
        ASSERT_TRUE(rig.startServer());
        ASSERT_TRUE(waitFor([&] { return rig.transport->state() == State::Connected; }));
        EXPECT_EQ(rig.transport->counters().reconnects, restart);
        EXPECT_TRUE(rig.acknowledge(command(cs2::SystemGo{0})).succeeded());
    }
}

// Liveness pings every 150 ms and calls four missed answers (600 ms) silence.
station::StationSettings quickLiveness() {
    station::StationSettings settings = sessionSettings();
    settings.liveness = {150ms, 4};
    return settings;
}

TEST(UdpStation, ThatFallsSilentIsReportedAndRecovers) {
    Rig rig(Wire::Udp, quickLiveness());
    ASSERT_TRUE(rig.start());
    station::Liveness& liveness = rig.session->liveness();
    QSignalSpy silent(&liveness, &station::Liveness::stationSilent);
    QSignalSpy recovered(&liveness, &station::Liveness::stationRecovered);
    QSignalSpy deviceSilent(&liveness, &station::Liveness::deviceSilent);
    liveness.start();

    rig.stopServer(); // UDP has no connection to lose: the station just stops answering
    QElapsedTimer clock;
    clock.start();
    ASSERT_TRUE(waitFor([&] { return silent.count() == 1; }));
    EXPECT_LT(clock.elapsed(), 3000);
    EXPECT_TRUE(liveness.isStationSilent());
    ASSERT_TRUE(waitFor([&] { return deviceSilent.count() == 1; }));
    EXPECT_EQ(deviceSilent.front().front().value<std::uint32_t>(), rig.station.uid());

    ASSERT_TRUE(rig.startServer());
    ASSERT_TRUE(waitFor([&] { return recovered.count() == 1; }));
    EXPECT_FALSE(liveness.isStationSilent());
    EXPECT_FALSE(liveness.isSilent(rig.station.uid()));
    EXPECT_EQ(silent.count(), 1);
    EXPECT_TRUE(rig.acknowledge(command(cs2::SystemGo{0})).succeeded());
}

TEST(UdpStation, ThatKeepsAnsweringIsNeverReportedSilent) {
    Rig rig(Wire::Udp, quickLiveness());
    ASSERT_TRUE(rig.start());
    QSignalSpy silent(&rig.session->liveness(), &station::Liveness::stationSilent);
    int answers = 0;
    QObject::connect(rig.session.get(), &station::StationSession::updated, rig.session.get(),
                     [&](const station::StationUpdates& updates) { answers += int(updates.devices.size()); });
    rig.session->liveness().start();
    // Ten answered pings: 1.5 s of pinging, more than twice the silence limit.
    ASSERT_TRUE(waitFor([&] { return answers >= 10; }));
    EXPECT_EQ(silent.count(), 0);
    EXPECT_FALSE(rig.session->liveness().isStationSilent());
}

} // namespace
} // namespace stellwerk::e2e
