// The book of block and memory function states (CS2 chapter 9, 0x30): what other programs announce on the
// bus is recorded per address, unknown values are kept and shown as unknown, Stellwerk's own block states go
// out as status answers on the block's address, and a memory function is requested from the master.

#include "ModelBench.h"
#include "can/FrameText.h"
#include "cs2/Codec.h"
#include "cs2/Header.h"

namespace stellwerk::model::test {
namespace {

using cs2::AutomationState;
using cs2::MemoryFunction;

constexpr std::uint16_t OtherHash = 0x2B11; // another program on the bus

can::CanFrame status(std::uint16_t device, std::uint16_t function, std::uint8_t value) {
    return cs2::encode(
        cs2::Message{0, true, OtherHash, cs2::AutomationSwitch{device, function, value, 0, std::nullopt}});
}

// Every 0x30 frame that reached the station, in the document's notation without the hash.
struct AutomationLog {
    explicit AutomationLog(ModelBench& bench) {
        QObject::connect(&bench.station, &sim::SimulatedStation::frameReceived, &context,
                         [this](const can::CanFrame& frame) {
                             if (cs2::command(frame) == std::uint8_t(cs2::Command::AutomationSwitch))
                                 frames.push_back(can::formatDocument(frame).substr(8));
                         });
    }
    QObject context;
    std::vector<std::string> frames;
};

class BlockStatesTest : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_TRUE(bench.start()); }

    BlockStates& book() { return bench.railway.blockStates(); }
    // Frames from the bus, as the station relays what another program says.
    void hear(const std::vector<can::CanFrame>& frames) { bench.stationEnd.sendBatch(frames); }

    ModelBench bench;
};

TEST_F(BlockStatesTest, RecordsTheStatesAnotherProgramAnnouncesOncePerBatch) {
    QSignalSpy changed(&book(), &BlockStates::changed);
    const std::uint16_t b3 = MemoryFunction::fromText("B3")->wire();
    hear({status(BlockStates::StellwerkDevice, b3, 4), status(0x0007, 0x4131, 6)});
    ASSERT_TRUE(waitFor([&] { return changed.count() == 1; }));
    EXPECT_EQ(changed.first().first().value<QList<AutomationAddress>>().size(), 2);
    // Block 11 is B3 on Stellwerk's device.
    ASSERT_TRUE(book().blockState(11).has_value());
    EXPECT_EQ(book().blockState(11)->state, AutomationState::BlockOccupied);
    EXPECT_FALSE(book().blockState(11)->isUnknown());
    EXPECT_FALSE(book().blockState(1).has_value()); // A1 was announced by device 7, not for our block 1
    const auto a1 = book().announcedAt({0x0007, 0x4131});
    ASSERT_TRUE(a1.has_value());
    EXPECT_EQ(a1->state, AutomationState::Reserved);
    EXPECT_EQ(book().memoryState(*MemoryFunction::fromText("A1"))->value, 6);
}

TEST_F(BlockStatesTest, AnUnknownValueIsKeptAndShownAsUnknown) {
    QSignalSpy changed(&book(), &BlockStates::changed);
    hear({status(BlockStates::StellwerkDevice, 0x4132, 7)});
    ASSERT_TRUE(waitFor([&] { return changed.count() == 1; }));
    const auto block2 = book().blockState(2);
    ASSERT_TRUE(block2.has_value());
    EXPECT_EQ(block2->value, 7);
    EXPECT_FALSE(block2->state.has_value());
    EXPECT_TRUE(block2->isUnknown());
    hear({status(BlockStates::StellwerkDevice, 0x4132, 255)}); // run error
    ASSERT_TRUE(waitFor([&] { return changed.count() == 2; }));
    EXPECT_TRUE(book().blockState(2)->isUnknown());
    EXPECT_EQ(book().blockState(2)->state, AutomationState::Error);
}

TEST_F(BlockStatesTest, TheLocomotiveInABlockIsRecorded) {
    QSignalSpy changed(&book(), &BlockStates::changed);
    const cs2::AutomationSwitch withLoco{BlockStates::StellwerkDevice, 0x4131, 0, 0, cs2::LocId(Br86)};
    hear({status(BlockStates::StellwerkDevice, 0x4131, 4),
          cs2::encode(cs2::Message{0, true, OtherHash, withLoco})});
    ASSERT_TRUE(waitFor([&] { return changed.count() == 1; }));
    ASSERT_TRUE(book().blockState(1)->loco.has_value());
    EXPECT_EQ(book().blockState(1)->loco->value(), Br86);
    EXPECT_EQ(book().blockState(1)->state, AutomationState::BlockOccupied); // kept from the status
}

TEST_F(BlockStatesTest, AGarbledAutomationFrameIsCountedAndRecordsNothing) {
    const auto before = bench.session.counters().undecodable;
    can::CanFrame garbled = status(BlockStates::StellwerkDevice, 0x4131, 4);
    garbled.dlc = 3; // no form of 9.1 has three bytes
    hear({garbled});
    ASSERT_TRUE(waitFor([&] { return bench.session.counters().undecodable == before + 1; }));
    EXPECT_TRUE(book().announced().empty());
}

TEST_F(BlockStatesTest, TheBookIsForgottenWhenTheStationIsLost) {
    QSignalSpy changed(&book(), &BlockStates::changed);
    hear({status(BlockStates::StellwerkDevice, 0x4131, 3)});
    ASSERT_TRUE(waitFor([&] { return changed.count() == 1; }));
    bench.appEnd.close();
    ASSERT_TRUE(waitFor([&] { return changed.count() == 2; }));
    EXPECT_TRUE(book().announced().empty());
    EXPECT_FALSE(book().blockState(1).has_value());
}

TEST_F(BlockStatesTest, OwnBlockStatesGoOutAsStatusAnswersOnTheBlocksAddress) {
    AutomationLog log(bench);
    EXPECT_TRUE(book().announce(1, BlockState::Free));
    EXPECT_TRUE(book().announce(2, BlockState::Occupied));
    EXPECT_TRUE(book().announce(9, BlockState::Reserved));
    EXPECT_TRUE(book().announce(16, BlockState::Waiting));
    EXPECT_TRUE(book().announce(416, BlockState::Unknown));
    EXPECT_FALSE(book().announce(417, BlockState::Free)); // beyond z8: no address
    EXPECT_FALSE(book().announce(0, BlockState::Free));
    ASSERT_TRUE(waitFor([&] { return log.frames.size() == 5; }));
    EXPECT_EQ(log.frames, (std::vector<std::string>{" 6 53 57 41 31 03 00", " 6 53 57 41 32 04 00",
                                                    " 6 53 57 42 31 06 00", " 6 53 57 42 38 05 00",
                                                    " 6 53 57 7A 38 FF 00"}));
    EXPECT_EQ(book().ownState(9), BlockState::Reserved);
    EXPECT_FALSE(book().ownState(3).has_value());
}

TEST_F(BlockStatesTest, AnnouncementsAreStatusAnswersWithOurHash) {
    std::vector<can::CanFrame> sent;
    QObject context;
    QObject::connect(&bench.station, &sim::SimulatedStation::frameReceived, &context,
                     [&](const can::CanFrame& frame) {
                         if (cs2::command(frame) == std::uint8_t(cs2::Command::AutomationSwitch))
                             sent.push_back(frame);
                     });
    ASSERT_TRUE(book().announce(3, BlockState::Occupied));
    ASSERT_TRUE(waitFor([&] { return !sent.empty(); }));
    EXPECT_TRUE(cs2::isResponse(sent.front()));
    EXPECT_EQ(cs2::hash(sent.front()), bench.session.identity().hash());
}

TEST(BlockStatesRoutes, ARoutesMemorySlotIsItsId) {
    EXPECT_EQ(BlockStates::memorySlotOfRoute(1), QStringLiteral("A1"));
    EXPECT_EQ(BlockStates::memorySlotOfRoute(9), QStringLiteral("B1"));
    EXPECT_EQ(BlockStates::memorySlotOfRoute(209), QStringLiteral("a1"));
    EXPECT_EQ(BlockStates::memorySlotOfRoute(416), QStringLiteral("z8"));
    EXPECT_TRUE(BlockStates::memorySlotOfRoute(417).isEmpty());
    EXPECT_TRUE(BlockStates::memorySlotOfRoute(0).isEmpty());
}

TEST(BlockStatesMeaning, EveryDocumentValueHasAMeaningAndTheRestAreUnknown) {
    const auto meaningOf = [](std::uint8_t value) {
        return AnnouncedState{value, cs2::automationStateOf(value), std::nullopt}.meaning();
    };
    EXPECT_EQ(meaningOf(0), AnnouncedMeaning::Deactivated);
    EXPECT_EQ(meaningOf(1), AnnouncedMeaning::Activated);
    EXPECT_EQ(meaningOf(2), AnnouncedMeaning::Running);
    EXPECT_EQ(meaningOf(3), AnnouncedMeaning::Free);
    EXPECT_EQ(meaningOf(4), AnnouncedMeaning::Occupied);
    EXPECT_EQ(meaningOf(5), AnnouncedMeaning::Waiting);
    EXPECT_EQ(meaningOf(6), AnnouncedMeaning::Reserved);
    EXPECT_EQ(meaningOf(254), AnnouncedMeaning::Waiting);
    EXPECT_EQ(meaningOf(255), AnnouncedMeaning::Unknown);
    EXPECT_EQ(meaningOf(7), AnnouncedMeaning::Unknown);
    EXPECT_EQ(meaningOf(100), AnnouncedMeaning::Unknown);
}

TEST_F(BlockStatesTest, RequestingAMemoryFunctionRunsItsRouteOnTheStation) {
    AutomationLog log(bench);
    ASSERT_TRUE(book().requestRoute(1));
    ASSERT_TRUE(waitFor([&] {
        const auto state = book().routeState(1);
        return state && state->meaning() == AnnouncedMeaning::Activated;
    }));
    ASSERT_FALSE(log.frames.empty());
    EXPECT_EQ(log.frames.front(), " 6 00 00 41 31 01 00"); // to the master, A1, activate
    // Route 1: W1 straight, S5 green, W2 to its third position; the railway saw the station switch them.
    ASSERT_TRUE(waitFor([&] { return bench.railway.accessory(2)->position() == 2; }));
    EXPECT_EQ(bench.railway.accessory(1)->position(), 1);
    EXPECT_EQ(bench.railway.accessory(5)->position(), 1);
}

} // namespace
} // namespace stellwerk::model::test
