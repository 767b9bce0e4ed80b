// The station's own automation command (CS2 chapter 9, 0x30) over real loopback sockets: a memory function
// requested from Stellwerk runs the demo's route on the simulated CS2, Stellwerk's block states reach another
// program on the same station, and a garbled 0x30 frame from that program is counted, not recorded.

#include "model/BlockStates.h"

#include "E2eSupport.h"
#include "cs2/Automation.h"
#include "cs2/Codec.h"

#include <memory>

namespace stellwerk::e2e {
namespace {

using cs2::AutomationState;
using cs2::MemoryFunction;
using model::BlockState;
using model::BlockStates;

// Another program on the same station: its own TCP connection, session and book.
struct OtherProgram {
    explicit OtherProgram(std::uint16_t tcpPort) {
        transport = transport::createTransport(
            transport::TcpSettings{QStringLiteral("127.0.0.1"), tcpPort, fastReconnect()});
        bus = std::make_unique<bus::Bus>(*transport, busreading::BusProfile::centralStation());
        station::StationSettings settings = sessionSettings();
        settings.uid = 0x53574B02;
        session = std::make_unique<station::StationSession>(*bus, settings);
        book = std::make_unique<BlockStates>(*session);
        transport->open();
    }
    bool connected() {
        return waitFor([&] { return transport->state() == transport::Transport::State::Connected; });
    }

    std::unique_ptr<transport::Transport> transport;
    std::unique_ptr<bus::Bus> bus;
    std::unique_ptr<station::StationSession> session;
    std::unique_ptr<BlockStates> book;
};

class BlockStatesOverSockets : public ::testing::TestWithParam<Wire> {};

// Demo route 2 "Einfahrt Gleis 2": A Einfahrsignal (6) green, W1 (1) round, P2 (8) red, W2 (2) round.
TEST_P(BlockStatesOverSockets, MemoryFunctionA2RunsTheDemosRouteTwo) {
    Rig rig(GetParam());
    ASSERT_TRUE(rig.start());
    ASSERT_EQ(rig.station.accessoryPosition(FirstTurnout), 1); // W1 starts straight
    BlockStates book(*rig.session);
    ASSERT_TRUE(book.requestMemoryFunction(*MemoryFunction::fromText("A2")));
    ASSERT_TRUE(waitFor([&] {
        const auto state = book.memoryState(*MemoryFunction::fromText("A2"));
        return state && state->state == AutomationState::Activated;
    }));
    EXPECT_EQ(rig.station.accessoryPosition(0x3005), 1); // A Einfahrsignal
    EXPECT_EQ(rig.station.accessoryPosition(0x3000), 0); // W1
    EXPECT_EQ(rig.station.accessoryPosition(0x3007), 0); // P2
    EXPECT_EQ(rig.station.accessoryPosition(0x3001), 0); // W2
}

INSTANTIATE_TEST_SUITE_P(Wires, BlockStatesOverSockets, ::testing::Values(Wire::Tcp, Wire::Udp),
                         [](const auto& info) { return wireName(info.param); });

TEST(BlockStatesBetweenPrograms, AnotherProgramSeesStellwerksBlockStates) {
    Rig rig(Wire::Tcp);
    ASSERT_TRUE(rig.start());
    OtherProgram other(rig.stationTcpPort());
    ASSERT_TRUE(other.connected());
    ASSERT_TRUE(waitFor([&] { return rig.server->tcpClientCount() >= 2; }));
    BlockStates ours(*rig.session);
    ASSERT_TRUE(ours.announce(12, BlockState::Reserved));
    ASSERT_TRUE(waitFor([&] { return other.book->blockState(12).has_value(); }));
    EXPECT_EQ(other.book->blockState(12)->state, AutomationState::Reserved);
    const auto address = BlockStates::addressOfBlock(12);
    EXPECT_EQ(address->device, BlockStates::StellwerkDevice);
    EXPECT_EQ(address->function, 0x4234); // B4
    EXPECT_TRUE(other.book->announcedAt(*address).has_value());
}

TEST(BlockStatesBetweenPrograms, AGarbledAutomationFrameIsCountedAndTheConversationGoesOn) {
    Rig rig(Wire::Tcp);
    ASSERT_TRUE(rig.start());
    OtherProgram other(rig.stationTcpPort());
    ASSERT_TRUE(other.connected());
    ASSERT_TRUE(waitFor([&] { return rig.server->tcpClientCount() >= 2; }));
    BlockStates ours(*rig.session);
    const auto before = rig.session->counters().undecodable;
    can::CanFrame garbled = cs2::encode(cs2::Message{
        0, true, 0, cs2::AutomationSwitch{BlockStates::StellwerkDevice, 0x4131, 4, 0, std::nullopt}});
    garbled.dlc = 3;
    ASSERT_TRUE(other.session->sendFrames({&garbled, 1}));
    ASSERT_TRUE(waitFor([&] { return rig.session->counters().undecodable == before + 1; }));
    EXPECT_TRUE(ours.announced().empty());
    ASSERT_TRUE(other.book->announce(1, BlockState::Occupied));
    ASSERT_TRUE(waitFor([&] { return ours.blockState(1).has_value(); }));
    EXPECT_EQ(ours.blockState(1)->state, AutomationState::BlockOccupied);
}

} // namespace
} // namespace stellwerk::e2e
