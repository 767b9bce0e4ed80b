// Start-up: ping lists the devices, status data is read, the configuration is downloaded, then the current
// states are asked for, including every S88 contact on the track plan (field notes: the station does not
// tell a late joiner).

#include "station/StartupSequence.h"

#include "ScriptedStation.h"

#include <QSignalSpy>

namespace stellwerk::station::test {
namespace {

constexpr const char* Locomotives = "[lokomotive]\nversion\n .minor=3\n"
                                    "lokomotive\n .name=BR 86\n .uid=0x4006\n .adresse=0x6\n .typ=mfx\n"
                                    " .funktionen\n ..nr=0\n ..typ=1\n .funktionen\n ..nr=1\n ..typ=2\n";
constexpr const char* TrackPlan = "[gleisbild]\nversion\n .major=1\ngroesse\nseite\n .name=Bahnhof\n";
constexpr const char* TrackPage = "[gleisbildseite]\nversion\n .major=1\n"
                                  "element\n .id=0x102\n .typ=s88kontakt\n .artikel=7\n .deviceId=0x100\n"
                                  "element\n .id=0x103\n .typ=gerade\n";

std::uint32_t word(const CanFrame& f, std::size_t at) {
    return std::uint32_t(f.data[at]) << 8 | f.data[at + 1];
}

// A station that acknowledges requests for files it does not have and sends no stream: short idle time.
StationSettings startupSettings() {
    StationSettings settings = Bench::fastSettings();
    settings.streamIdle = 150ms;
    return settings;
}

struct StartupBench : Bench {
    StartupBench() : Bench(startupSettings()) {
        std::vector<std::uint8_t> summary{0, 0, 0, 0, 0, 0, 0x30, 0x39, '6', '0', '1', '1', '3', 0, 0, 0};
        for (char c : std::string_view("Gleisbox"))
            summary.push_back(std::uint8_t(c));
        summary.push_back(0);
        station.statusData[{ScriptedStation::Uid, 0}] = summary;
        station.files["loks"] = Locomotives;
        station.files["gbs"] = TrackPlan;
        station.files["gbs-0"] = TrackPage;
    }

    StartupOptions options() const {
        StartupOptions o;
        o.deviceWindow = 100ms;
        return o;
    }
};

TEST(StartupSequence, ListsDevicesDownloadsTheLayoutAndAsksForTheCurrentStates) {
    StartupBench bench;
    StartupSequence startup(bench.session, bench.options());
    QSignalSpy ready(&startup, &StartupSequence::ready);
    QSignalSpy steps(&startup, &StartupSequence::stepStarted);
    QSignalSpy progress(&startup, &StartupSequence::downloadProgress);
    startup.start();
    ASSERT_TRUE(waitFor([&] { return ready.count() == 1; }));
    const StartupResult& result = startup.result();

    ASSERT_EQ(result.devices.size(), 1u);
    ASSERT_TRUE(result.devices[0].summary);
    EXPECT_EQ(result.devices[0].summary->article, "60113");
    EXPECT_EQ(result.devices[0].identity.deviceType, 0x0010);

    ASSERT_TRUE(result.locomotives);
    ASSERT_EQ(result.locomotives->locomotives.size(), 1u);
    EXPECT_EQ(result.files.at("loks"), Locomotives);
    ASSERT_TRUE(result.trackPlan);
    ASSERT_EQ(result.pages.size(), 1u);
    EXPECT_EQ(result.pages[0].name, "Bahnhof");
    EXPECT_FALSE(result.accessories) << "no magnetartikel.cs2 served";
    EXPECT_FALSE(result.routes);
    EXPECT_GE(result.problems.size(), 2) << "mags and fs are reported missing";
    EXPECT_GE(progress.count(), 3);

    // Speed, direction, F0, F1 of the loco, and the one contact on the plan.
    EXPECT_EQ(result.stateQueries, 5u);
    EXPECT_EQ(result.stateAnswers, 5u);
    EXPECT_EQ(bench.station.count(cs2::Command::LocoSpeed), 1u);
    EXPECT_EQ(bench.station.count(cs2::Command::LocoFunction), 2u);
    ASSERT_EQ(bench.station.count(cs2::Command::S88Event), 1u);
    for (const auto& f : bench.station.received)
        if (cs2::command(f) == std::uint8_t(cs2::Command::S88Event)) {
            EXPECT_EQ(f.dlc, 4) << "the query form";
            EXPECT_EQ(word(f, 0), 0x100u);
            EXPECT_EQ(word(f, 2), 7u);
        }
    ASSERT_GE(steps.count(), 4);
    EXPECT_EQ(steps.first().at(0).value<StartupSequence::Step>(), StartupSequence::Step::Devices);
    EXPECT_EQ(startup.step(), StartupSequence::Step::Ready);
}

TEST(StartupSequence, GleisboxWakeUpSendsGoAndEnablesTheTrackProtocols) {
    StartupBench bench;
    StartupOptions options = bench.options();
    options.wakeGleisbox = true;
    options.downloadConfiguration = false;
    StartupSequence startup(bench.session, options);
    QSignalSpy ready(&startup, &StartupSequence::ready);
    startup.start();
    ASSERT_TRUE(waitFor([&] { return ready.count() == 1; }));
    ASSERT_EQ(bench.station.count(cs2::Command::BootloaderCan), 1u);
    for (const auto& f : bench.station.received) {
        if (cs2::command(f) == std::uint8_t(cs2::Command::BootloaderCan)) {
            EXPECT_EQ(f, frame(0x1B, false, bench.session.identity().hash(), {0, 0, 0, 0, 0x11}));
        }
        if (cs2::command(f) == std::uint8_t(cs2::Command::System)) {
            EXPECT_EQ(f, frame(0x00, false, bench.session.identity().hash(), {0, 0, 0, 0, 0x08, 0x07}));
        }
    }
}

TEST(StartupSequence, WithoutAnyDeviceTheStartupStillEndsAndSaysWhy) {
    StartupBench bench;
    bench.station.silent = true;
    StartupSequence startup(bench.session, bench.options());
    QSignalSpy ready(&startup, &StartupSequence::ready);
    startup.start();
    ASSERT_TRUE(waitFor([&] { return ready.count() == 1; }));
    EXPECT_TRUE(startup.result().devices.empty());
    EXPECT_FALSE(startup.result().locomotives);
    EXPECT_GE(startup.result().problems.size(), 5) << "no device, and each of loks, mags, fs, gbs";
}

} // namespace
} // namespace stellwerk::station::test
