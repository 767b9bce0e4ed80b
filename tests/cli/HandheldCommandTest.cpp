// stellwerk-cli --station URL handhelds against the simulated CS2's bus with an MS1 on it, over loopback
// TCP: as the master it prints one line per event (JSON lines with --json), drives the station with what
// the handheld does, and leaves the railway as it was when it ends; as a watcher it only listens.

#include "CliApplication.h"
#include "CliTestSupport.h"
#include "StationCommand.h"
#include "sim/SimulatedBus.h"
#include "sim/SimulatedMs1.h"
#include "sim/SimulatedStation.h"
#include "sim/StationLayout.h"
#include "sim/StationServer.h"

#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>
#include <csignal>
#include <gtest/gtest.h>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace stellwerk::cli {
namespace {

using test::Outcome;

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> result;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        result.push_back(line);
    return result;
}

// The demo's CS2 as a Gleisbox-like station (no handhelds' master) with one MS1 on its bus, behind TCP.
// The MS1 takes the first locomotive of its stack once it has read it, and drives at step 64.
class HandheldCommandTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { test::ensureApplication(); }

    void SetUp() override {
        bus.attach(station);
        bus.attach(ms1);
        sim::StationServerSettings settings;
        settings.listenAddress = QHostAddress::LocalHost;
        settings.udp = false;
        settings.tcpPort = 0;
        server = std::make_unique<sim::StationServer>(station, bus, settings);
        ASSERT_TRUE(server->listen()) << server->errorString().toStdString();
        QObject::connect(&ms1, &sim::SimulatedMs1::upgradeDone, &ms1, [this] { ms1.takeLoco(0); });
        QObject::connect(&ms1, &sim::SimulatedMs1::locoTaken, &ms1,
                         [this] { ms1.setSpeed(64, sim::SimulatedMs1::Direction::Forward); });
    }

    Outcome run(const std::vector<std::string>& command) {
        std::vector<std::string> arguments{"tcp://127.0.0.1:" + std::to_string(server->tcpPort())};
        arguments.insert(arguments.end(), command.begin(), command.end());
        std::ostringstream out, err;
        const int status = runStation(arguments, out, err);
        return {status, out.str(), err.str()};
    }

    static sim::SimulatedStation::Options noMaster() {
        sim::SimulatedStation::Options options;
        options.handheldMaster = false;
        return options;
    }
    static sim::SimulatedMs1::Options quickMs1() {
        sim::SimulatedMs1::Options options;
        options.identity.uid = 0x000204B3;
        options.identity.name = "KS\x1b[31mMS1"; // a terminal escape in its name
        options.timing.pollPeriod = std::chrono::milliseconds(20);
        options.timing.loginRetry = std::chrono::milliseconds(150);
        return options;
    }
    std::uint32_t firstLoco() const { return station.layout().locomotives().locomotives.front().uid; }

    sim::SimulatedBus bus;
    sim::SimulatedStation station{sim::StationLayout::demo(), noMaster()};
    sim::SimulatedMs1 ms1{quickMs1()};
    std::unique_ptr<sim::StationServer> server;
};

TEST_F(HandheldCommandTest, AsMasterItPrintsJsonLinesOfTheHandheldsEventsAndDrivesTheStation) {
    QTimer::singleShot(500, &ms1, [this] { ms1.plugIn(); }); // once the start-up has listed the devices
    const Outcome result = run({"handhelds", "--json", "--seconds", "3"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.err.find("Stellwerk is the handhelds' master"), std::string::npos) << result.err;

    std::vector<std::string> events;
    std::set<QString> names;
    for (const std::string& line : lines(result.out)) {
        QJsonParseError error;
        const QJsonDocument json = QJsonDocument::fromJson(QByteArray::fromStdString(line), &error);
        ASSERT_EQ(error.error, QJsonParseError::NoError) << line;
        const QJsonObject event = json.object();
        events.push_back(event.value("event").toString().toStdString());
        EXPECT_EQ(event.value("uid").toString(), QStringLiteral("0x000204B3")) << line;
        names.insert(event.value("name").toString());
        if (events.back() == "speed") {
            EXPECT_EQ(event.value("speed").toInt(), 64) << line;
            EXPECT_EQ(event.value("direction").toString(), QStringLiteral("forward")) << line;
        }
    }
    EXPECT_TRUE(names.contains(QStringLiteral("KS?[31mMS1"))) << "its name, once told, without the escape";
    EXPECT_EQ(result.out.find('\x1b'), std::string::npos) << "no escape reaches a terminal";
    const std::vector<std::string> expected{"login", "upgrade-done", "loco-taken", "speed"};
    ASSERT_GE(events.size(), expected.size()) << result.out;
    EXPECT_EQ(std::vector<std::string>(events.begin(), events.begin() + 4), expected) << result.out;
    ASSERT_NE(station.loco(firstLoco()), nullptr);
    EXPECT_EQ(station.loco(firstLoco())->speed, 504) << "the handheld's speed reached the station";
    EXPECT_EQ(station.power(), sim::SimulatedStation::Power::Stopped) << "ending switched nothing";
}

TEST_F(HandheldCommandTest, AsWatcherItAnswersNoHandheld) {
    QTimer::singleShot(500, &ms1, [this] { ms1.plugIn(); });
    const Outcome result = run({"handhelds", "--watch", "--seconds", "2"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.err.find("watching the handhelds only (asked)"), std::string::npos) << result.err;
    EXPECT_NE(ms1.phase(), sim::SimulatedMs1::Phase::Online) << "nobody answered its login";
}

TEST_F(HandheldCommandTest, AnUnknownArgumentIsRefusedWithTheChoices) {
    const Outcome result = run({"handhelds", "--loud"});
    EXPECT_NE(result.status, 0);
    EXPECT_NE(result.err.find(
                  "handhelds: unknown argument '--loud' (takes --json, --master, --watch, --seconds N)"),
              std::string::npos)
        << result.err;
    EXPECT_TRUE(result.out.empty());
}

// Ctrl+C ends it with 0; the railway stays as the handheld left it (nothing is sent on the way out).
TEST_F(HandheldCommandTest, CtrlCEndsItCleanlyAndLeavesTheRailwayAsItWas) {
    QTimer::singleShot(500, &ms1, [this] { ms1.plugIn(); });
    QTimer watch; // once the handheld's speed reached the station, a person presses Ctrl+C
    watch.start(50);
    QObject::connect(&watch, &QTimer::timeout, &ms1, [this, &watch] {
        if (station.loco(firstLoco()) && station.loco(firstLoco())->speed == 504) {
            watch.stop();
            std::raise(SIGINT);
        }
    });
    const Outcome result = run({"handhelds"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.out.find("speed 0x000204B3"), std::string::npos) << result.out;
    ASSERT_NE(station.loco(firstLoco()), nullptr);
    EXPECT_EQ(station.loco(firstLoco())->speed, 504) << "ending changed no locomotive";
    EXPECT_EQ(station.power(), sim::SimulatedStation::Power::Stopped) << "ending switched nothing";
}

} // namespace
} // namespace stellwerk::cli
