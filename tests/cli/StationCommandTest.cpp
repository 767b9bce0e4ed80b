// stellwerk-cli --station URL COMMAND against a real simulated CS2 behind real loopback sockets (TCP and
// UDP, ports picked free): every command waits for the station's acknowledgement and says so.

#include "StationCommand.h"

#include "CliApplication.h"
#include "CliTestSupport.h"
#include "PingOnlyDevice.h"
#include "cs2/Codec.h"
#include "sim/SimulatedStation.h"
#include "sim/StationLayout.h"
#include "sim/StationServer.h"

#include <QCoreApplication>
#include <QProcess>
#include <QTest>
#include <QTimer>
#include <QUdpSocket>
#include <filesystem>
#include <gtest/gtest.h>
#include <memory>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace stellwerk::cli {
namespace {

using test::Outcome;

constexpr std::uint32_t CentralStationUid = 0x43533201;
constexpr std::uint32_t GleisboxUid = 0x47431001;

// The cli tests run on gtest_main; the station commands need an application for their event loop. It is
// never deleted: Qt objects of other tests may outlive any owner we could give it.
// A UDP port nobody uses right now (the system's choice, released again).
std::uint16_t freeStationUdpPort() {
    QUdpSocket probe;
    EXPECT_TRUE(probe.bind(QHostAddress::LocalHost, 0));
    return probe.localPort();
}

std::size_t countLines(const std::string& text) {
    return std::size_t(std::count(text.begin(), text.end(), '\n'));
}

// A simulated CS2 with a Gleisbox on its bus, serving the demo layout on loopback TCP and UDP; its UDP
// replies go to `cliUdpPort_`, where the command line listens (udp://...?listen=).
class StationCommandTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { test::ensureApplication(); }

    void SetUp() override {
        sim::SimulatedStation::Options options;
        options.gleisbox = true;
        station_ = std::make_unique<sim::SimulatedStation>(sim::StationLayout::demo(), options);
        cliUdpPort_ = freeStationUdpPort();
        sim::StationServerSettings settings;
        settings.listenAddress = QHostAddress::LocalHost;
        settings.udpPort = 0;
        settings.tcpPort = 0;
        settings.udpReplyHost = QHostAddress::LocalHost;
        settings.udpReplyPort = cliUdpPort_;
        server_ = std::make_unique<sim::StationServer>(*station_, settings);
        ASSERT_TRUE(server_->listen()) << server_->errorString().toStdString();
    }

    std::string tcpUrl() const { return "tcp://127.0.0.1:" + std::to_string(server_->tcpPort()); }
    std::string udpUrl() const {
        return "udp://127.0.0.1:" + std::to_string(server_->udpPort()) +
               "?listen=" + std::to_string(cliUdpPort_);
    }

    Outcome run(const std::string& url, const std::vector<std::string>& command) {
        std::vector<std::string> arguments{url};
        arguments.insert(arguments.end(), command.begin(), command.end());
        std::ostringstream out, err;
        const int status = runStation(arguments, out, err);
        return {status, out.str(), err.str()};
    }
    Outcome run(const std::vector<std::string>& command) { return run(tcpUrl(), command); }

    std::unique_ptr<sim::SimulatedStation> station_;
    std::unique_ptr<sim::StationServer> server_;
    std::uint16_t cliUdpPort_ = 0;
};

// ---- 3.4-3.6: locomotives -------------------------------------------------------------------------

TEST_F(StationCommandTest, SpeedOfAnMfxLocoIsAcknowledged) {
    const Outcome result = run({"speed", "mfx:5", "500"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(result.out, "ok: loco mfx:5 speed 500 (acknowledged)\n");
    ASSERT_NE(station_->loco(0x4005), nullptr);
    EXPECT_EQ(station_->loco(0x4005)->speed, 500);
}

TEST_F(StationCommandTest, SpeedOfADccLocoByRawLocIdIsAcknowledged) {
    const Outcome result = run({"speed", "0xC003", "1000"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(result.out, "ok: loco dcc:3 speed 1000 (acknowledged)\n");
    ASSERT_NE(station_->loco(0xC003), nullptr);
    EXPECT_EQ(station_->loco(0xC003)->speed, 1000);
}

TEST_F(StationCommandTest, DirectionToggleReportsWhereTheLocoNowGoes) {
    ASSERT_EQ(run({"direction", "mm2:72", "forward"}).status, 0);
    const Outcome result = run({"direction", "mm2:72", "toggle"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(result.out, "ok: loco mm2:72 direction toggle -> backward (acknowledged)\n");
    ASSERT_NE(station_->loco(0x0048), nullptr);
    EXPECT_EQ(station_->loco(0x0048)->direction, 2);
}

TEST_F(StationCommandTest, FunctionOnAndOffAreAcknowledged) {
    Outcome result = run({"function", "dcc:3", "2", "on"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(result.out, "ok: loco dcc:3 function 2 on (acknowledged)\n");
    ASSERT_NE(station_->loco(0xC003), nullptr);
    EXPECT_EQ(station_->loco(0xC003)->functions[2], 1);

    result = run({"function", "dcc:3", "2", "off"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(station_->loco(0xC003)->functions[2], 0);
}

// ---- 4.1: accessories (1-based keyboard numbers) ----------------------------------------------------

TEST_F(StationCommandTest, SwitchUsesTheKeyboardNumber) {
    const Outcome result = run({"switch", "5", "green"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(result.out, "ok: accessory mm2:5 position 1 (acknowledged)\n");
    EXPECT_EQ(station_->accessoryPosition(0x3004), std::optional<std::uint8_t>(1));
}

TEST_F(StationCommandTest, SwitchADccAccessoryToRed) {
    ASSERT_EQ(run({"switch", "dcc:12", "1"}).status, 0);
    const Outcome result = run({"switch", "dcc:12", "red"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(result.out, "ok: accessory dcc:12 position 0 (acknowledged)\n");
    EXPECT_EQ(station_->accessoryPosition(0x380B), std::optional<std::uint8_t>(0));
}

// ---- 2.1-2.3: track power ---------------------------------------------------------------------------

TEST_F(StationCommandTest, GoHaltAndStopAreAcknowledged) {
    Outcome result = run({"go"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(result.out, "ok: system go (acknowledged)\n");
    EXPECT_EQ(station_->power(), sim::SimulatedStation::Power::Running);

    result = run({"halt"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(result.out, "ok: system halt (acknowledged)\n");
    EXPECT_EQ(station_->power(), sim::SimulatedStation::Power::Halted);

    result = run({"stop"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(result.out, "ok: system stop (acknowledged)\n");
    EXPECT_EQ(station_->power(), sim::SimulatedStation::Power::Stopped);
}

TEST_F(StationCommandTest, GoToTheStationByUid) {
    const Outcome result = run({"go", "0x43533201"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(result.out, "ok: system go 0x43533201 (acknowledged)\n");
    EXPECT_EQ(station_->power(), sim::SimulatedStation::Power::Running);
}

// ---- 6.1: ping --------------------------------------------------------------------------------------

TEST_F(StationCommandTest, PingListsTheCentralStationAndTheGleisbox) {
    const Outcome result = run({"ping"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.out.find("0x43533201  version "), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("Central Station"), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("0x47431001  version "), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("type 0x0010  Gleisbox"), std::string::npos) << result.out;
    EXPECT_EQ(countLines(result.out), 2u) << result.out;
}

// ---- 7: configuration data --------------------------------------------------------------------------

TEST_F(StationCommandTest, DownloadLoksWritesTheServedFile) {
    const auto file = std::filesystem::temp_directory_path() /
                      ("stellwerk-cli-loks-" + std::to_string(server_->tcpPort()) + ".cs2");
    const Outcome result = run({"download", "loks", "-o", file.string()});
    EXPECT_EQ(result.status, 0) << result.err;
    const auto served = station_->layout().fileForKey("loks");
    ASSERT_TRUE(served.has_value());
    EXPECT_EQ(test::readFile(file), *served);
    EXPECT_EQ(result.out, "ok: download loks: " + std::to_string(served->size()) + " bytes written to " +
                              file.string() + " (acknowledged)\n");
    EXPECT_NE(result.err.find("downloading loks: 100%"), std::string::npos) << result.err;
    std::filesystem::remove(file);
}

TEST_F(StationCommandTest, DownloadWithoutFileWritesToStandardOutput) {
    const Outcome result = run({"download", "mags"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(result.out, station_->layout().fileForKey("mags").value_or("missing"));
}

// ---- 6.2 and system 0x0B: status data and readings ---------------------------------------------------

TEST_F(StationCommandTest, StatusOfOneDevicePrintsEveryReadingWithItsUnit) {
    const Outcome result = run({"status", "0x47431001"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_TRUE(
        std::regex_search(result.out, std::regex("^0x47431001 Gleisbox \\(60113, serial [0-9]+\\)\n")))
        << result.out;
    EXPECT_TRUE(std::regex_search(result.out, std::regex("\n  TRACK: [0-9]+\\.[0-9]{2} A\n"))) << result.out;
    EXPECT_TRUE(std::regex_search(result.out, std::regex("\n  VOLT: [0-9]+\\.[0-9]{2} Volt\n")))
        << result.out;
    EXPECT_TRUE(std::regex_search(result.out, std::regex("\n  TEMP: [0-9]+\\.[0-9] C\n"))) << result.out;
}

TEST_F(StationCommandTest, StatusWithoutUidReadsEveryDeviceThatAnswersThePing) {
    const Outcome result = run({"status"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.out.find("0x43533201 "), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("0x47431001 Gleisbox"), std::string::npos) << result.out;
    EXPECT_TRUE(std::regex_search(result.out, std::regex("\n  VOLT: [0-9]+\\.[0-9] V\n"))) << result.out;
    EXPECT_TRUE(std::regex_search(result.out, std::regex("\n  TEMP: [0-9]+ C\n"))) << result.out;
}

TEST_F(StationCommandTest, StatusOfADeviceThatIsNotThereIsNotAcknowledged) {
    const Outcome result = run({"status", "0x12345678"});
    EXPECT_EQ(result.status, 1);
    EXPECT_NE(result.err.find("error: 0x12345678: "), std::string::npos) << result.err;
}

// A PC program on the bus answers the ping but has no status data: the readings of the station and the
// Gleisbox are printed all the same, the program is named, and the command succeeds.
TEST_F(StationCommandTest, StatusNamesADeviceWithoutStatusDataAndPrintsTheOthers) {
    const test::PingOnlyDevice program(server_->tcpPort());
    ASSERT_TRUE(program.connected());
    const Outcome result = run({"status"});
    EXPECT_EQ(result.status, 0) << result.out << result.err;
    EXPECT_GE(program.pingsAnswered(), 1);
    EXPECT_NE(result.out.find("0x47431001 Gleisbox"), std::string::npos) << result.out;
    EXPECT_TRUE(std::regex_search(result.out, std::regex("\n  TRACK: [0-9]+\\.[0-9]{2} A\n"))) << result.out;
    EXPECT_NE(result.out.find("0x43533201 "), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("0x50435057 CS2 software (PC), type 0xEEEE: no status data\n"),
              std::string::npos)
        << result.out;
    EXPECT_EQ(result.err, "") << result.err;
}

// Asked for by its UID, a device without status data is what the command could not do.
TEST_F(StationCommandTest, StatusOfOneDeviceWithoutStatusDataIsNotAcknowledged) {
    const test::PingOnlyDevice program(server_->tcpPort());
    ASSERT_TRUE(program.connected());
    const Outcome result = run({"status", "0x50435057"});
    EXPECT_EQ(result.status, 1);
    EXPECT_NE(result.out.find("0x50435057"), std::string::npos) << result.out;
    EXPECT_NE(result.err.find("error: 0x50435057: "), std::string::npos) << result.err;
}

// ---- monitor ----------------------------------------------------------------------------------------

// The station reports S88 contacts changing every 50 ms while the monitor runs.
class ContactChanges {
public:
    explicit ContactChanges(sim::SimulatedStation& station) {
        QObject::connect(&timer_, &QTimer::timeout, &timer_, [&station, this] {
            occupied_ = !occupied_;
            station.setContact(1, 7, occupied_);
        });
        timer_.start(50);
    }

private:
    QTimer timer_;
    bool occupied_ = false;
};

TEST_F(StationCommandTest, MonitorPrintsFramesUntilTheCount) {
    const ContactChanges changes(*station_);
    const Outcome result = run({"monitor", "--count", "3"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(countLines(result.out), 3u) << result.out;
    EXPECT_NE(result.out.find("feedback.s88-event"), std::string::npos) << result.out;
}

TEST_F(StationCommandTest, MonitorJsonPrintsOneObjectPerFrame) {
    const ContactChanges changes(*station_);
    const Outcome result = run({"monitor", "--json", "--count", "2"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_TRUE(std::regex_match(result.out, std::regex("(\\{\"id\":\"[0-9A-F]{8}\".*\\}\n){2}")))
        << result.out;
    EXPECT_NE(result.out.find("\"name\":\"feedback.s88-event\""), std::string::npos) << result.out;
}

// ---- resync: bringing the layout back in step (issue 32) ----------------------------------------------

// Another controller (an MS2) drives a locomotive on the station's bus.
void drivenByAnotherController(sim::SimulatedStation& station, std::uint32_t loco, std::uint16_t speed) {
    station.receive(cs2::encode(cs2::Message{0, false, 0x2F11, cs2::LocoSpeed{cs2::LocId(loco), speed}}));
}

TEST_F(StationCommandTest, ResyncSendsEveryLocoItsConfirmedSpeedAndPrintsEveryStateReadAgain) {
    drivenByAnotherController(*station_, 0x4001, 300);
    const Outcome result = run({"resync"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_TRUE(std::regex_search(result.out, std::regex("^ok: sent 12 locomotives their confirmed speed and "
                                                         "read [0-9]+ states again\n")))
        << result.out;
    EXPECT_NE(result.out.find("\nBR 218 Ost (0x4001): speed 300, forward"), std::string::npos) << result.out;
    EXPECT_EQ(countLines(result.out), 13U) << "the summary and one line per locomotive";
    EXPECT_EQ(station_->loco(0x4001)->speed, 300) << "its confirmed speed, sent again";
}

TEST_F(StationCommandTest, ResyncStopStopsEveryLoco) {
    drivenByAnotherController(*station_, 0x4001, 300);
    drivenByAnotherController(*station_, 0x0018, 500);
    const Outcome result = run({"resync", "--stop"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(result.out.rfind("ok: stopped 12 locomotives and read ", 0), 0U) << result.out;
    EXPECT_NE(result.out.find("BR 218 Ost (0x4001): speed 0"), std::string::npos) << result.out;
    EXPECT_EQ(station_->loco(0x4001)->speed, 0);
    EXPECT_EQ(station_->loco(0x0018)->speed, 0);
}

TEST_F(StationCommandTest, ResyncTakesOnlyStop) {
    const Outcome result = run({"resync", "--all"});
    EXPECT_EQ(result.status, 2);
    EXPECT_NE(result.err.find("resync: unknown argument '--all' (takes --stop)"), std::string::npos)
        << result.err;
}

// ---- UDP: the station replies to the port the command line listens on --------------------------------

TEST_F(StationCommandTest, PingOverUdp) {
    const Outcome result = run(udpUrl(), {"ping"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.out.find("0x43533201  version "), std::string::npos) << result.out;
}

TEST_F(StationCommandTest, SpeedOverUdp) {
    const Outcome result = run(udpUrl(), {"speed", "dcc:3", "250"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(result.out, "ok: loco dcc:3 speed 250 (acknowledged)\n");
    ASSERT_NE(station_->loco(0xC003), nullptr);
    EXPECT_EQ(station_->loco(0xC003)->speed, 250);
}

// ---- the program itself: main() gives the station commands their application ---------------------------

TEST_F(StationCommandTest, TheProgramExitsWithZeroWhenTheStationAcknowledged) {
    QProcess cli;
    cli.start(STELLWERK_CLI, {"--station", QString::fromStdString(tcpUrl()), "speed", "dcc:3", "700"});
    ASSERT_TRUE(QTest::qWaitFor([&] { return cli.state() == QProcess::NotRunning; }, 10000));
    EXPECT_EQ(cli.exitStatus(), QProcess::NormalExit);
    EXPECT_EQ(cli.exitCode(), 0) << cli.readAllStandardError().toStdString();
    EXPECT_EQ(cli.readAllStandardOutput().toStdString(), "ok: loco dcc:3 speed 700 (acknowledged)\n");
    ASSERT_NE(station_->loco(0xC003), nullptr);
    EXPECT_EQ(station_->loco(0xC003)->speed, 700);
}

// ---- failures -----------------------------------------------------------------------------------------

TEST_F(StationCommandTest, NobodyAnsweringIsNotAcknowledged) {
    const std::uint16_t silent = freeStationUdpPort();
    const std::string url =
        "udp://127.0.0.1:" + std::to_string(silent) + "?listen=" + std::to_string(freeStationUdpPort());
    const Outcome result = run(url, {"speed", "mfx:5", "500"});
    EXPECT_EQ(result.status, 1);
    EXPECT_EQ(result.out, "");
    EXPECT_EQ(result.err, "error: loco mfx:5 speed 500: no acknowledgement after 3 attempt(s)\n");
}

TEST_F(StationCommandTest, AClosedPortCannotBeOpened) {
    const std::uint16_t port = server_->tcpPort();
    server_.reset(); // nobody listens there any more
    const Outcome result = run("tcp://127.0.0.1:" + std::to_string(port), {"ping"});
    EXPECT_EQ(result.status, 3);
    EXPECT_NE(
        result.err.find("stellwerk-cli: cannot open the transport: tcp://127.0.0.1:" + std::to_string(port)),
        std::string::npos)
        << result.err;
}

TEST_F(StationCommandTest, AWrongLocIsAUsageError) {
    const Outcome result = run({"speed", "mfx:99999", "500"});
    EXPECT_EQ(result.status, 2);
    EXPECT_EQ(result.err, "stellwerk-cli: LOC 'mfx:99999': the address does not fit the mfx range\n");
}

TEST_F(StationCommandTest, UsageErrorsComeBeforeTheTransportIsOpened) {
    EXPECT_EQ(run("tcp://127.0.0.1:1", {"speed", "mfx:5", "1001"}).status, 2);
    EXPECT_EQ(run("tcp://127.0.0.1:1", {"direction", "mfx:5", "sideways"}).status, 2);
    EXPECT_EQ(run("tcp://127.0.0.1:1", {"switch", "0", "green"}).status, 2);
    EXPECT_EQ(run("tcp://127.0.0.1:1", {"fly"}).status, 2);
    EXPECT_EQ(run("nowhere://x", {"ping"}).status, 2);
}

} // namespace
} // namespace stellwerk::cli
