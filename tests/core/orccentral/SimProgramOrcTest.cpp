// The real stellwerk-sim with --orc-booster, --orc-decoders N and --orc-encoders N: the options are listed
// and checked, and Stellwerk's OpenRailCAN central, on the station's TCP port (29-bit frames in the 13-byte
// network form), finds what they put on the bus, switches a decoder the simulator prints, sees an encoder's
// input change and the booster's overload come and go.
#include "OrcRig.h"
#include "SimProgram.h"
#include "orc/Codec.h"
#include "transport/TcpTransport.h"

#include <QSignalSpy>
#include <algorithm>
#include <bit>
#include <memory>

namespace stellwerk::orccentral::test {
namespace {

using support::Quiet;
using support::SimProgram;

TEST(SimProgramOrc, HelpListsTheOrcOptions) {
    SimProgram help({"--help"});
    EXPECT_EQ(help.exitCode(), 0);
    for (const char* option : {"--orc-booster", "--orc-overload-after <ms>", "--orc-overload-port <port>",
                               "--orc-decoders <N>", "--orc-encoders <N>", "--orc-encoder-toggle <ms>",
                               "--orc-throttle <ziel-id>", "--orc-throttle-every <ms>"})
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
        {{"--orc-throttle", "0x10000"}, "--orc-throttle: '0x10000' is not a Ziel-Id 0..0xFFFF"},
        {{"--orc-throttle", "0x4001", "--orc-throttle-every", "0"},
         "--orc-throttle-every: '0' is not 1..600000 milliseconds"},
        {{"--orc-throttle-every", "100"}, "--orc-throttle-every needs --orc-throttle"},
        {{"--ms1", "1", "--orc-decoders", "1"},
         "--ms1 and OpenRailCAN devices cannot share the station's bus: M-CAN overlaps OpenRailCAN there"},
    };
    for (const auto& [arguments, message] : cases) {
        SimProgram refused(arguments);
        EXPECT_EQ(refused.exitCode(), 2) << arguments.join(' ').toStdString();
        EXPECT_TRUE(refused.output().contains(message)) << refused.output().toStdString();
    }
}

// The simulator with every kind of device, and the central on its TCP port.
class SimProgramWithDevices : public ::testing::Test {
protected:
    void SetUp() override {
        const std::uint16_t port = sim.tcpPort();
        ASSERT_NE(port, 0) << sim.output().toStdString();
        EXPECT_TRUE(sim.printed("OpenRailCAN: a booster, 2 decoder(s), 1 encoder(s) on the station's bus"));
        wire = std::make_unique<transport::TcpTransport>(
            transport::TcpSettings{QStringLiteral("127.0.0.1"), port, {}});
        bus = std::make_unique<bus::Bus>(*wire, busreading::BusProfile::openRailCan(), QStringLiteral("CS2"));
        central = std::make_unique<OrcSession>(*bus, fastSettings());
        wire->open();
        ASSERT_TRUE(waitFor([&] { return wire->state() == transport::Transport::State::Connected; }));
        central->start();
        ASSERT_TRUE(waitFor([&] { return onlineCount() == 4; })) << central->devices().size();
    }
    std::size_t onlineCount() const {
        return std::size_t(std::ranges::count_if(
            central->devices(), [](const OrcDevice& d) { return d.state == OrcDevice::State::Online; }));
    }

    SimProgram sim{QStringList{"--orc-booster", "--orc-overload-after", "300", "--orc-overload-port", "2",
                               "--orc-decoders", "2", "--orc-encoders", "1", "--orc-encoder-toggle", "200"} +
                   Quiet};
    std::unique_ptr<transport::TcpTransport> wire;
    std::unique_ptr<bus::Bus> bus;
    std::unique_ptr<OrcSession> central;
};

TEST_F(SimProgramWithDevices, TheCentralFindsTheBoosterDecodersAndEncoderOverTcp) {
    const std::vector<std::tuple<std::uint32_t, std::uint16_t, orc::DeviceType>> expected{
        {0x3A2E0300, 0x0300, orc::DeviceType::System},
        {0x3A2E0101, 0x0101, orc::DeviceType::CanDecoder},
        {0x3A2E0102, 0x0102, orc::DeviceType::CanDecoder},
        {0x3A2E0201, 0x0201, orc::DeviceType::CanEncoder}};
    for (const auto& [uid, busId, type] : expected) {
        const OrcDevice* device = central->device(uid);
        ASSERT_NE(device, nullptr) << std::hex << uid;
        EXPECT_EQ(device->busId, busId) << "the low 16 bits of its UID, which are free";
        EXPECT_EQ(device->state, OrcDevice::State::Online) << std::hex << uid;
        EXPECT_EQ(device->type, std::uint8_t(type)) << std::hex << uid;
    }
}

TEST_F(SimProgramWithDevices, TheSecondDecoderConfirmsASwitchTheSimulatorPrints) {
    QSignalSpy switched(central.get(), &OrcSession::switchReported);
    central->switchOutputs(0x0102, 0x05);
    ASSERT_TRUE(waitFor([&] { return switched.count() == 1; }));
    EXPECT_EQ(switched.at(0).at(2).value<OrcSession::SwitchResult>(), OrcSession::SwitchResult::Confirmed);
    EXPECT_TRUE(sim.printed("ORC decoder 0x0102: outputs 00000101")) << sim.output().toStdString();
    EXPECT_FALSE(sim.output().contains("ORC decoder 0x0101: outputs")) << "decoder 1 was not switched";
}

// The clock started with the simulator, and the central asks the encoder for its inputs once when it comes
// online: the later changes are events of one input each, inputs 0..31 in turn.
TEST_F(SimProgramWithDevices, TheEncodersInputsChangeOneAtATime) {
    QSignalSpy inputs(central.get(), &OrcSession::inputsChanged);
    const auto changes = [&inputs] {
        std::vector<std::uint32_t> changed;
        for (const QList<QVariant>& report : inputs)
            if (report.at(2).toUInt() != 0)
                changed.push_back(report.at(2).toUInt());
        return changed;
    };
    ASSERT_TRUE(waitFor([&] { return changes().size() >= 2; })) << "an input changes every 200 ms";
    EXPECT_EQ(inputs.at(0).at(0).toUInt(), 0x0201u);
    const std::vector<std::uint32_t> changed = changes();
    const std::uint32_t first = changed[changed.size() - 2], second = changed.back();
    EXPECT_EQ(std::popcount(first), 1) << "one input at a time";
    EXPECT_TRUE(second == first << 1 || (first == 0x80000000u && second == 1u)) << "inputs 0..31 in turn";
}

// Überlast on the port --orc-overload-port named, then "Nix" (cleared).
TEST_F(SimProgramWithDevices, TheBoostersOverloadComesAndGoes) {
    QSignalSpy overloads(central.get(), &OrcSession::overloadChanged);
    const auto seen = [&overloads](std::uint8_t kind, qsizetype after) {
        for (qsizetype i = after + 1; i < overloads.count(); ++i)
            if (overloads.at(i).at(2).toUInt() == kind)
                return i;
        return qsizetype(-1);
    };
    ASSERT_TRUE(waitFor([&] { return seen(1, -1) >= 0 && seen(0, seen(1, -1)) >= 0; }));
    const QList<QVariant> report = overloads.at(seen(1, -1));
    EXPECT_EQ(report.at(0).toUInt(), 0x0300u);
    EXPECT_EQ(report.at(1).toUInt(), 2u);
    EXPECT_TRUE(sim.printed("ORC booster: port 2 overloaded"));
}

// --orc-throttle: a throttle (device type 1) that the central finds, sending Lok Speed (D=0) for its loco,
// 300 and 0 in turn, for a central that forwards it to the station.
TEST(SimProgramOrc, TheThrottleDrivesItsLocoNowAndThen) {
    SimProgram sim(QStringList{"--orc-throttle", "0x4001", "--orc-throttle-every", "200"} + Quiet);
    const std::uint16_t port = sim.tcpPort();
    ASSERT_NE(port, 0) << sim.output().toStdString();
    transport::TcpTransport wire(transport::TcpSettings{QStringLiteral("127.0.0.1"), port, {}});
    bus::Bus bus(wire, busreading::BusProfile::openRailCan(), QStringLiteral("CS2"));
    OrcSession central(bus, fastSettings());
    std::vector<orc::LocoSpeed> speeds;
    QObject context;
    bus.subscribe(busreading::Protocol::Orc, &context, [&speeds](const std::vector<can::CanFrame>& frames) {
        for (const can::CanFrame& frame : frames)
            if (const auto message = orc::decode(frame); std::holds_alternative<orc::LocoSpeed>(message))
                speeds.push_back(std::get<orc::LocoSpeed>(message));
    });
    wire.open();
    ASSERT_TRUE(waitFor([&] { return wire.state() == transport::Transport::State::Connected; }));
    central.start();
    ASSERT_TRUE(waitFor([&] { return speeds.size() >= 2 && central.device(0x3A2E0400); }));
    EXPECT_EQ(central.device(0x3A2E0400)->type, std::uint8_t(orc::DeviceType::Loco));
    for (const orc::LocoSpeed& speed : speeds) {
        EXPECT_FALSE(speed.answer);
        EXPECT_EQ(speed.target, 0x4001);
        EXPECT_EQ(speed.from.busId, 0x0400);
    }
    EXPECT_NE(speeds[0].speed, speeds[1].speed) << "300 and 0 in turn";
    EXPECT_TRUE(sim.printed("ORC throttle: Lok Speed 0x4001 300"));
}

} // namespace
} // namespace stellwerk::orccentral::test
