// stellwerk-cli --station URL orc ...: Stellwerk as the OpenRailCAN central on the simulated CS2's bus, with
// an 8-output decoder and a 32-input encoder there, reached over loopback TCP. The exit status says
// whether a device answered (0) or none did (1); the simulated devices show what really happened.

#include "CliApplication.h"
#include "CliTestSupport.h"
#include "OrcCommand.h"
#include "StationCommand.h"
#include "sim/SimulatedBus.h"
#include "sim/SimulatedOrcDevices.h"
#include "sim/SimulatedStation.h"
#include "sim/StationLayout.h"
#include "sim/StationServer.h"

#include <QCoreApplication>
#include <QTest>
#include <QTimer>
#include <gtest/gtest.h>
#include <memory>
#include <sstream>

namespace stellwerk::cli {
namespace {

using test::Outcome;

constexpr std::uint32_t DecoderUid = 0x3A2E0101; // bus id 0x0101
constexpr std::uint32_t EncoderUid = 0x3A2E0102; // bus id 0x0102

class OrcStationCommandTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { test::ensureApplication(); }

    void SetUp() override {
        bus.attach(station);
        bus.attach(decoder);
        bus.attach(encoder);
        decoder.plugIn();
        encoder.plugIn();
        sim::StationServerSettings settings;
        settings.listenAddress = QHostAddress::LocalHost;
        settings.udp = false;
        settings.tcpPort = 0;
        server = std::make_unique<sim::StationServer>(station, bus, settings);
        ASSERT_TRUE(server->listen()) << server->errorString().toStdString();
    }

    Outcome run(const std::vector<std::string>& command) {
        std::vector<std::string> arguments{"tcp://127.0.0.1:" + std::to_string(server->tcpPort()), "orc"};
        arguments.insert(arguments.end(), command.begin(), command.end());
        std::ostringstream out, err;
        const int status = runStation(arguments, out, err);
        return {status, out.str(), err.str()};
    }

    sim::SimulatedBus bus;
    sim::SimulatedStation station{sim::StationLayout::demo()};
    sim::SimulatedOrcDecoder decoder{DecoderUid};
    sim::SimulatedOrcEncoder encoder{EncoderUid};
    std::unique_ptr<sim::StationServer> server;
};

TEST_F(OrcStationCommandTest, FindListsTheDevicesThatAnswered) {
    Outcome result = run({"find"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.out.find("device uid=0x3A2E0101 busId=0x0101 type=can-decoder version=0x0102 online\n"),
              std::string::npos)
        << result.out;
    EXPECT_NE(result.out.find("device uid=0x3A2E0102 busId=0x0102 type=can-encoder version=0x0102 online\n"),
              std::string::npos)
        << result.out;
    EXPECT_NE(result.out.find("2 device(s) answered\n"), std::string::npos) << result.out;
    result = run({"--json", "find"});
    EXPECT_NE(result.out.find("{\"event\":\"device\",\"uid\":\"0x3A2E0101\",\"busId\":\"0x0101\",\"type\":"
                              "\"can-decoder\",\"version\":\"0x0102\",\"state\":\"online\"}"),
              std::string::npos)
        << result.out;
}

TEST_F(OrcStationCommandTest, FindWithoutDevicesExitsOne) {
    QTest::qWait(100); // the announcements of their plugging in pass while nobody listens
    decoder.unplug();
    encoder.unplug();
    const Outcome result = run({"find"});
    EXPECT_EQ(result.status, NotAcknowledged);
    EXPECT_EQ(result.out, "0 device(s) answered\n");
}

// dekoder schalten to the decoder's bus id: Pos is the state of its outputs.
TEST_F(OrcStationCommandTest, SwitchWaitsForTheDecodersAcknowledgement) {
    Outcome result = run({"switch", "0x0101", "0x05"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(result.out, "switch target=0x0101 position=0x05: confirmed\n");
    EXPECT_EQ(decoder.outputs(), 0x05);
    result = run({"--json", "switch", "0x0101", "0"});
    EXPECT_EQ(result.out,
              "{\"command\":\"switch\",\"target\":\"0x0101\",\"position\":\"0x00\",\"answered\":true,"
              "\"outcome\":\"confirmed\"}\n");
    EXPECT_EQ(decoder.outputs(), 0x00);
}

TEST_F(OrcStationCommandTest, ASwitchNobodyAcknowledgesExitsOne) {
    const Outcome result = run({"switch", "0x3005", "1"}); // MM2 turnout 5: no decoder here answers
    EXPECT_EQ(result.status, NotAcknowledged);
    EXPECT_EQ(result.out, "switch target=0x3005 position=0x01: sent, unconfirmed\n");
}

TEST_F(OrcStationCommandTest, WatchPrintsTheEncodersInputsAsTheyChange) {
    QTimer::singleShot(500, &encoder, [this] { encoder.setInput(3, true); });
    const Outcome result = run({"--json", "--seconds", "1", "watch"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.out.find("\"uid\":\"0x3A2E0102\""), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("{\"event\":\"inputs\",\"encoder\":\"0x0102\",\"inputs\":\"0x00000008\","
                              "\"changed\":\"0x00000008\"}"),
              std::string::npos)
        << result.out;
}

TEST_F(OrcStationCommandTest, BadArgumentsAreUsageErrors) {
    Outcome result = run({"switch", "0x10000", "1"});
    EXPECT_EQ(result.status, UsageError);
    EXPECT_NE(result.err.find("orc switch: TARGET is a Ziel-Id 0..0xFFFF, POS 0..255"), std::string::npos)
        << result.err;
    result = run({"ping"});
    EXPECT_EQ(result.status, UsageError);
    EXPECT_NE(result.err.find("orc: takes [--json] [--seconds N] and find, switch TARGET POS or watch"),
              std::string::npos)
        << result.err;
}

} // namespace
} // namespace stellwerk::cli
