// The real stellwerk-sim with --orc-booster, --orc-decoders N and --orc-encoders N: the options are listed
// and checked, and Stellwerk's OpenRailCAN central, on the station's TCP port (29-bit frames in the 13-byte
// network form), finds what they put on the bus, switches a decoder the simulator prints, sees an encoder's
// input change and the booster's overload come and go.
#include "OrcRig.h"
#include "SimProgram.h"
#include "transport/TcpTransport.h"

#include <QSignalSpy>
#include <bit>

namespace stellwerk::orccentral::test {
namespace {

using support::Quiet;
using support::SimProgram;

TEST(SimProgramOrc, HelpListsTheOrcOptions) {
    SimProgram help({"--help"});
    EXPECT_EQ(help.exitCode(), 0);
    for (const char* option : {"--orc-booster", "--orc-overload-after <ms>", "--orc-overload-port <port>",
                               "--orc-decoders <N>", "--orc-encoders <N>", "--orc-encoder-toggle <ms>"})
        EXPECT_TRUE(help.output().contains(QString::fromLatin1(option))) << option;
}

// Each bad value is an error (exit 2) that names the option and what it takes.
TEST(SimProgramOrc, BadValuesAreRefusedWithTheReason) {
    const std::vector<std::pair<QStringList, QString>> cases{
        {{"--orc-decoders", "65"}, "--orc-decoders: '65' is not 0..64"},
        {{"--orc-encoders", "-1"}, "--orc-encoders: '-1' is not 0..64"},
        {{"--orc-booster", "--orc-overload-after", "soon"},
         "--orc-overload-after: 'soon' is not 0..600000 milliseconds"},
        {{"--orc-booster", "--orc-overload-port", "255"}, "--orc-overload-port: '255' is not a port 0..254"},
        {{"--orc-encoders", "1", "--orc-encoder-toggle", "1.5"},
         "--orc-encoder-toggle: '1.5' is not 0..600000 milliseconds"},
        {{"--orc-overload-after", "100"}, "--orc-overload-after and --orc-overload-port need --orc-booster"},
        {{"--ms1", "1", "--orc-decoders", "1"},
         "--ms1 and OpenRailCAN devices cannot share the station's bus: M-CAN overlaps OpenRailCAN there"},
    };
    for (const auto& [arguments, message] : cases) {
        SimProgram refused(arguments);
        EXPECT_EQ(refused.exitCode(), 2) << arguments.join(' ').toStdString();
        EXPECT_TRUE(refused.output().contains(message)) << refused.output().toStdString();
    }
}

class SimProgramWithDevices : public ::testing::Test {
protected:
    SimProgram sim{QStringList{"--orc-booster", "--orc-overload-after", "300", "--orc-overload-port", "2",
                               "--orc-decoders", "2", "--orc-encoders", "1", "--orc-encoder-toggle", "200"} +
                   Quiet};
};

TEST_F(SimProgramWithDevices, TheCentralFindsTheBoosterDecodersAndEncoderOverTcp) {
    const std::uint16_t port = sim.tcpPort();
    ASSERT_NE(port, 0) << sim.output().toStdString();
    EXPECT_TRUE(sim.printed("OpenRailCAN: a booster, 2 decoder(s), 1 encoder(s) on the station's bus"));

    transport::TcpTransport wire(transport::TcpSettings{QStringLiteral("127.0.0.1"), port, {}});
    buses::Bus bus(wire, bus::BusProfile::openRailCan(), QStringLiteral("CS2"));
    OrcSession central(bus, fastSettings());
    QSignalSpy inputs(&central, &OrcSession::inputsChanged);
    QSignalSpy overloads(&central, &OrcSession::overloadChanged);
    wire.open();
    ASSERT_TRUE(waitFor([&] { return wire.state() == transport::Transport::State::Connected; }));
    central.start();
    ASSERT_TRUE(waitFor([&] { return central.devices().size() == 4; })) << central.devices().size();
    const std::vector<std::tuple<std::uint32_t, std::uint16_t, orc::DeviceType>> expected{
        {0x3A2E0300, 0x0300, orc::DeviceType::System},
        {0x3A2E0101, 0x0101, orc::DeviceType::CanDecoder},
        {0x3A2E0102, 0x0102, orc::DeviceType::CanDecoder},
        {0x3A2E0201, 0x0201, orc::DeviceType::CanEncoder}};
    for (const auto& [uid, busId, type] : expected) {
        ASSERT_TRUE(waitFor([&] { return central.device(uid) && central.device(uid)->busId == busId; }))
            << std::hex << uid;
        EXPECT_EQ(central.device(uid)->state, OrcDevice::State::Online) << std::hex << uid;
        EXPECT_EQ(central.device(uid)->type, std::uint8_t(type)) << std::hex << uid;
    }

    QSignalSpy switched(&central, &OrcSession::switchReported);
    central.switchOutputs(0x0102, 0x05);
    ASSERT_TRUE(waitFor([&] { return switched.count() == 1; }));
    EXPECT_EQ(switched.at(0).at(2).value<OrcSession::SwitchResult>(), OrcSession::SwitchResult::Confirmed);
    EXPECT_TRUE(sim.printed("ORC decoder 0x0102: outputs 00000101")) << sim.output().toStdString();
    EXPECT_FALSE(sim.output().contains("ORC decoder 0x0101: outputs")) << "decoder 1 was not switched";

    // The clocks started with the simulator, and the central asks the encoder for its inputs once when it
    // comes online: the later changes are events of one input each, inputs 0..31 in turn.
    const auto changes = [&inputs] {
        std::vector<std::uint32_t> changed;
        for (const QList<QVariant>& report : inputs)
            if (report.at(2).toUInt() != 0)
                changed.push_back(report.at(2).toUInt());
        return changed;
    };
    ASSERT_TRUE(waitFor([&] { return changes().size() >= 3; })) << "an input changes every 200 ms";
    EXPECT_EQ(inputs.at(0).at(0).toUInt(), 0x0201u);
    const std::vector<std::uint32_t> changed = changes();
    const std::uint32_t first = changed[changed.size() - 2], second = changed.back();
    EXPECT_EQ(std::popcount(first), 1) << "one input at a time";
    EXPECT_TRUE(second == first << 1 || (first == 0x80000000u && second == 1u)) << "inputs 0..31 in turn";
    const auto seen = [&overloads](std::uint8_t kind, qsizetype after) {
        for (qsizetype i = after + 1; i < overloads.count(); ++i)
            if (overloads.at(i).at(2).toUInt() == kind)
                return i;
        return qsizetype(-1);
    };
    ASSERT_TRUE(waitFor([&] { return seen(1, -1) >= 0 && seen(0, seen(1, -1)) >= 0; }));
    const QList<QVariant> report = overloads.at(seen(1, -1));
    EXPECT_EQ(report.at(0).toUInt(), 0x0300u);
    EXPECT_EQ(report.at(1).toUInt(), 2u) << "the port --orc-overload-port named";
    EXPECT_TRUE(sim.printed("ORC booster: port 2 overloaded"));
}

} // namespace
} // namespace stellwerk::orccentral::test
