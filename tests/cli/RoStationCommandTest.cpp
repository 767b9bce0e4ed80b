// stellwerk-cli --station URL ro ...: an RO module on the simulated CS2's bus, reached over loopback TCP.
// The exit status says whether the module answered (0 done, 1 no answer, 4 refused); the module's own
// register file shows what really happened.

#include "CliApplication.h"
#include "CliTestSupport.h"
#include "RoCommand.h"
#include "StationCommand.h"
#include "sim/SimulatedBus.h"
#include "sim/SimulatedRoModule.h"
#include "sim/SimulatedStation.h"
#include "sim/StationLayout.h"
#include "sim/StationServer.h"

#include <QCoreApplication>
#include <QTimer>
#include <gtest/gtest.h>
#include <memory>
#include <sstream>

namespace stellwerk::cli {
namespace {

using test::Outcome;

const std::string Module1 = "req=0x01FE0001,resp=0x01FF0001";

class RoStationCommandTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { test::ensureApplication(); }

    void SetUp() override {
        bus.attach(station);
        bus.attach(module);
        sim::StationServerSettings settings;
        settings.listenAddress = QHostAddress::LocalHost;
        settings.udp = false;
        settings.tcpPort = 0;
        server = std::make_unique<sim::StationServer>(station, bus, settings);
        ASSERT_TRUE(server->listen()) << server->errorString().toStdString();
    }

    Outcome run(const std::vector<std::string>& command) {
        std::vector<std::string> arguments{"tcp://127.0.0.1:" + std::to_string(server->tcpPort()), "ro"};
        arguments.insert(arguments.end(), command.begin(), command.end());
        std::ostringstream out, err;
        const int status = runStation(arguments, out, err);
        return {status, out.str(), err.str()};
    }

    sim::SimulatedBus bus;
    sim::SimulatedStation station{sim::StationLayout::demo()};
    sim::SimulatedRoModule module{ro::RoProfile::simulator(1)};
    std::unique_ptr<sim::StationServer> server;
};

// 004 §3.3: the byte 0x0F written at 0x0012.
TEST_F(RoStationCommandTest, Section3_3_WriteAndReadBack) {
    Outcome result = run({"--module", Module1, "write", "0x0012", "byte", "0x0F"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(result.out, "write address=0x0012 width=byte value=0x0F: done\n");
    EXPECT_EQ(module.registers().byteAt(0x0012), 0x0F);
    result = run({"--module", Module1, "--json", "read", "0x0012", "byte"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(result.out,
              "{\"command\":\"read\",\"address\":\"0x0012\",\"width\":\"byte\",\"value\":\"0x0F\","
              "\"answered\":true,\"outcome\":\"done\"}\n");
}

// 004 §3.4: relay 14 on; switched once, and only after the relays were read.
TEST_F(RoStationCommandTest, Section3_4_SwitchRelay14) {
    const Outcome result = run({"--module", Module1, "switch", "14", "on"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(result.out, "switch relay=14 on: done relays=0x2000\n");
    EXPECT_TRUE(module.relay(14));
    ASSERT_EQ(module.writes().size(), 1u);
    EXPECT_EQ(module.writes().front().value, 0x2000u);
}

TEST_F(RoStationCommandTest, ExitStatusSaysWhetherTheModuleAnswered) {
    module.unplug();
    Outcome result = run({"--module", Module1, "--json", "read", "0x0020", "word"});
    EXPECT_EQ(result.status, 1);
    EXPECT_NE(result.out.find("\"answered\":false,\"outcome\":\"no answer\""), std::string::npos)
        << result.out;
    module.plugIn();
    result = run({"--module", Module1, "read", "0xFFFE", "long"}); // past 0xFFFF: 0xFE (notes R13)
    EXPECT_EQ(result.status, RefusedByModule);
    EXPECT_EQ(result.out, "read address=0xFFFE width=long value=0x00000000: invalid command (0xFE)\n");
}

TEST_F(RoStationCommandTest, WatchPrintsTheInputsAsTheyChange) {
    QTimer::singleShot(400, &module, [this] { module.setInput(3, true); });
    const Outcome result = run({"--module", Module1, "--json", "watch", "--seconds", "1"});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.out.find("{\"event\":\"online\"}"), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("{\"event\":\"inputs\",\"inputs\":\"0x0004\",\"changed\":\"0x0004\"}"),
              std::string::npos)
        << result.out;
}

TEST_F(RoStationCommandTest, ElevenBitModulesAndBadArgumentsAreRefused) {
    Outcome result = run({"--module", "req=0x700,resp=0x701,std", "read", "0", "word"});
    EXPECT_EQ(result.status, UsageError);
    EXPECT_NE(result.err.find("11-bit frames travel through a CAN adapter (QCanBus) only"), std::string::npos)
        << result.err;
    result = run({"read", "0", "word"});
    EXPECT_EQ(result.status, UsageError);
    EXPECT_NE(result.err.find("ro: --module req=ID,resp=ID[,std] is missing"), std::string::npos)
        << result.err;
    result = run({"--module", Module1, "write", "0x12", "byte", "0x100"});
    EXPECT_NE(result.err.find("ro write: VALUE 0x100 does not fit a byte"), std::string::npos) << result.err;
    result = run({"--module", Module1, "switch", "17", "on"});
    EXPECT_NE(result.err.find("ro switch: RELAY is 1..16"), std::string::npos) << result.err;
}

} // namespace
} // namespace stellwerk::cli
