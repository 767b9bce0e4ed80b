// Placing a train by block, as the track plan does (its block menu, a locomotive dropped on a block), and
// taking it off again: the train stands where it was put, holds that block alone, is moved with everything
// it held, and a block another train holds or has reserved is refused with a sentence.
#include "AutomationTestSupport.h"
#include "automation/Dispatcher.h"

#include <algorithm>

namespace stellwerk::automation {
namespace {

using namespace test;
using Kind = AutomationEvent::Kind;
using trackgraph::End;

constexpr std::uint32_t Br218 = 0x4001, Ice = 0x4002;

int countOf(const std::vector<AutomationEvent>& events, Kind kind) {
    return int(std::count_if(events.begin(), events.end(), [kind](const auto& e) { return e.kind == kind; }));
}

TEST(PlaceInBlock, ATrainStandsInTheBlockFacingTheEndGivenAndHoldsIt) {
    Dispatcher dispatcher(demo());
    ASSERT_EQ(dispatcher.placeInBlock(Br218, "BR 218", 180, Gleis2, End::A), std::nullopt);
    const TrainBody* body = dispatcher.tracking().body(Br218);
    ASSERT_NE(body, nullptr);
    EXPECT_EQ(body->frontBlock, Gleis2);
    EXPECT_EQ(body->towards, End::A);
    EXPECT_EQ(body->lengthMm, 180);
    EXPECT_EQ(dispatcher.tracking().trainIn(Gleis2), Br218);
    EXPECT_EQ(dispatcher.reservations().blocksOf(Br218), std::vector<int>{Gleis2});
    EXPECT_EQ(dispatcher.train(Br218)->mode, TrainMode::Manual);
    const std::vector<AutomationEvent> events = dispatcher.takeEvents();
    ASSERT_EQ(countOf(events, Kind::Placed), 1);
    EXPECT_EQ(events.back().block, Gleis2);
    EXPECT_EQ(events.back().text, "BR 218 placed in \"Gleis 2\" facing end a");
}

TEST(PlaceInBlock, PlacedAgainElsewhereTheTrainLeavesWhatItHeldBefore) {
    Dispatcher dispatcher(demo());
    ASSERT_EQ(dispatcher.placeInBlock(Br218, "BR 218", 200, Gleis1, End::B), std::nullopt);
    ASSERT_EQ(dispatcher.placeInBlock(Br218, "BR 218", 200, Block3, End::B), std::nullopt);
    EXPECT_EQ(dispatcher.tracking().trainIn(Gleis1), 0U);
    EXPECT_EQ(dispatcher.reservations().blockOwner(Gleis1), 0U) << "the block it stood in is free again";
    EXPECT_EQ(dispatcher.reservations().blocksOf(Br218), std::vector<int>{Block3});
}

TEST(PlaceInBlock, ABlockAnotherTrainHoldsIsRefusedWithItsName) {
    Dispatcher dispatcher(demo());
    ASSERT_EQ(dispatcher.placeInBlock(Ice, "ICE 3", 200, Gleis1, End::B), std::nullopt);
    const std::optional<std::string> refused = dispatcher.placeInBlock(Br218, "BR 218", 200, Gleis1, End::B);
    ASSERT_TRUE(refused.has_value());
    EXPECT_EQ(*refused, "BR 218: block \"Gleis 1\" holds ICE 3 already");
    EXPECT_EQ(dispatcher.train(Br218), nullptr);
    EXPECT_FALSE(dispatcher.placeInBlock(Br218, "BR 218", 200, 99, End::B) == std::nullopt)
        << "a block the plan does not have";
}

TEST(PlaceInBlock, ABlockReservedForAnotherTrainsWayIsRefused) {
    Dispatcher dispatcher(demo());
    ASSERT_EQ(dispatcher.placeInBlock(Ice, "ICE 3", 200, Gleis1, End::B), std::nullopt);
    dispatcher.occupancyRead({contact(1)});
    dispatcher.setMode(Ice, TrainMode::Automatic, 0);
    dispatcher.tick(0); // its way: Ausfahrt Ost, Block 1
    ASSERT_EQ(dispatcher.reservations().blockOwner(Block1), Ice);
    const std::optional<std::string> refused = dispatcher.placeInBlock(Br218, "BR 218", 200, Block1, End::B);
    ASSERT_TRUE(refused.has_value());
    EXPECT_EQ(*refused, "BR 218: block \"Block 1\" is reserved for ICE 3");
}

TEST(PlaceInBlock, ATrainTakenOffIsNoLongerTrackedAndGivesBackWhatItHeld) {
    Dispatcher dispatcher(demo());
    ASSERT_EQ(dispatcher.placeInBlock(Br218, "BR 218", 200, Gleis1, End::B), std::nullopt);
    dispatcher.occupancyRead({contact(1)});
    dispatcher.setMode(Br218, TrainMode::Automatic, 0);
    dispatcher.tick(0);
    ASSERT_GT(dispatcher.reservations().blocksOf(Br218).size(), 1U);
    dispatcher.takeCommands();
    dispatcher.takeEvents();
    EXPECT_TRUE(dispatcher.remove(Br218));
    EXPECT_EQ(dispatcher.train(Br218), nullptr);
    EXPECT_EQ(dispatcher.tracking().body(Br218), nullptr);
    EXPECT_TRUE(dispatcher.reservations().blocksOf(Br218).empty());
    EXPECT_TRUE(dispatcher.reservations().connectionsOf(Br218).empty());
    EXPECT_EQ(dispatcher.takeCommands(), std::vector<DriveCommand>{DriveCommand::speedOf(Br218, 0)})
        << "a train the automation drove is stopped";
    const std::vector<AutomationEvent> events = dispatcher.takeEvents();
    ASSERT_EQ(events.size(), 1U);
    EXPECT_EQ(events.front().kind, Kind::Released);
    EXPECT_EQ(events.front().text, "BR 218 taken off \"Gleis 1\": no longer tracked");
    EXPECT_FALSE(dispatcher.remove(Br218));
}

} // namespace
} // namespace stellwerk::automation
