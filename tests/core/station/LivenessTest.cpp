// Field notes: a station pings periodically; one that stops answering is silent, and recovers when it
// answers again.

#include "ScriptedStation.h"

#include <QElapsedTimer>
#include <QSignalSpy>

namespace stellwerk::station::test {
namespace {

TEST(Liveness, PingsPeriodically) {
    Bench bench;
    bench.session.liveness().start();
    ASSERT_TRUE(waitFor([&] { return bench.station.count(cs2::Command::Ping) >= 3; }));
    EXPECT_FALSE(bench.session.liveness().isStationSilent());
}

TEST(Liveness, StationThatStopsAnsweringIsSilentWithinTheConfiguredTimeAndRecovers) {
    Bench bench; // ping every 50 ms, silent after 3 missed intervals (150 ms)
    QSignalSpy silent(&bench.session.liveness(), &Liveness::stationSilent);
    QSignalSpy recovered(&bench.session.liveness(), &Liveness::stationRecovered);
    QSignalSpy deviceSilent(&bench.session.liveness(), &Liveness::deviceSilent);
    bench.session.liveness().start();
    ASSERT_TRUE(waitFor([&] { return bench.session.devices().size() == 1; }));

    bench.station.silent = true;
    QElapsedTimer clock;
    clock.start();
    ASSERT_TRUE(waitFor([&] { return silent.count() == 1; }));
    EXPECT_LT(clock.elapsed(), 1500) << "150 ms of silence plus one interval, with room for a loaded machine";
    EXPECT_GE(clock.elapsed(), 90);
    EXPECT_TRUE(bench.session.liveness().isStationSilent());
    ASSERT_EQ(deviceSilent.count(), 1);
    EXPECT_EQ(deviceSilent.at(0).at(0).value<std::uint32_t>(), ScriptedStation::Uid);

    bench.station.silent = false;
    ASSERT_TRUE(waitFor([&] { return recovered.count() == 1; }));
    EXPECT_FALSE(bench.session.liveness().isStationSilent());
    EXPECT_FALSE(bench.session.liveness().isSilent(ScriptedStation::Uid));
    EXPECT_EQ(silent.count(), 1) << "reported once, not on every tick";
}

TEST(Liveness, NoAnswerAtAllIsSilence) {
    Bench bench;
    bench.station.silent = true;
    QSignalSpy silent(&bench.session.liveness(), &Liveness::stationSilent);
    bench.session.liveness().start();
    ASSERT_TRUE(waitFor([&] { return silent.count() == 1; }));
}

} // namespace
} // namespace stellwerk::station::test
