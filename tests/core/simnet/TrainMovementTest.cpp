// Trains on the track graph of the demo's own plan: running locomotives occupy and release the S88 contacts
// their length covers, in the direction they run, and follow the turnouts as the station has them set. The
// contacts are reached in the order of the hand-written table the graph replaced (core/sim/DemoLayoutTrack,
// retired), with W1, W2 and W3 choosing the way as they did there.

#include "sim/TrainMovement.h"

#include "TrainTestSupport.h"

#include <gtest/gtest.h>
#include <vector>

namespace stellwerk::sim {
namespace {

using namespace std::chrono_literals;
using test::ContactEvent;
using trackgraph::End;

constexpr std::uint32_t MovingBr218 = 0x4001;
constexpr std::uint8_t Branch = 0, Straight = 1;

// The demo's contacts the trains are placed on: Gleis 1, Einfahrt West, Ausfahrt Ost.
constexpr std::int64_t Gleis1 = 1, EinfahrtWest = 7, AusfahrtOst = 8;

class TrainMovementTest : public ::testing::Test {
protected:
    // Places BR 218 Ost (again, freeing what it covered) with no S88 event recorded yet.
    void placeBr218(std::int64_t contact, End towards) {
        if (!rig_.movement)
            rig_.place({});
        ASSERT_EQ(rig_.movement->place({MovingBr218, contact, towards}), std::nullopt);
        rig_.contacts.events.clear();
    }
    std::string frontBlock() { return rig_.blockName(rig_.at(MovingBr218).block); }
    // Sets a turnout with the train stopped, and waits until it has moved (200 ms).
    void settle(std::uint32_t keyboard, std::uint8_t position) {
        rig_.drive(MovingBr218, 0);
        rig_.setTurnout(keyboard, position);
        rig_.run(300ms);
    }

    test::TrainRig rig_{StationLayout::demo()};
};

TEST_F(TrainMovementTest, APlacedTrainCoversItsContactFromTheStart) {
    rig_.place({{MovingBr218, Gleis1, End::B}});
    EXPECT_EQ(rig_.contacts.events, (std::vector<ContactEvent>{{1, true}}));
    EXPECT_TRUE(rig_.station.contact(0, 1));
    EXPECT_EQ(rig_.movement->occupantOf(0, 1), MovingBr218);
    // Gleis 1 is 1,260 mm long with its contact at 360..540 mm: the front stands at the contact's far edge.
    EXPECT_EQ(frontBlock(), "Gleis 1");
    EXPECT_EQ(rig_.at(MovingBr218).frontMm, 540);
    EXPECT_EQ(rig_.at(MovingBr218).towards, End::B);
    EXPECT_TRUE(rig_.movement->problems().empty());
}

// What a real station cannot say and the simulator can: which train is on which contact.
TEST_F(TrainMovementTest, TellsWhichTrainComesOntoAContactAndWhenItLeaves) {
    std::vector<std::pair<std::uint16_t, std::uint32_t>> told; // contact, Loc-ID
    rig_.place({});
    QObject::connect(rig_.movement.get(), &TrainMovement::occupantChanged,
                     [&told](std::uint16_t, std::uint16_t contact, std::uint32_t locId) {
                         told.emplace_back(contact, locId);
                     });
    ASSERT_EQ(rig_.movement->place({MovingBr218, Gleis1, End::B}), std::nullopt);
    EXPECT_EQ(told, (std::vector<std::pair<std::uint16_t, std::uint32_t>>{{1, MovingBr218}}))
        << "placed on Gleis 1";
    told.clear();
    rig_.drive(MovingBr218, 1000);
    rig_.run(2s); // 1,000 mm at 500 mm/s: off Gleis 1's contact and onto Ausfahrt Ost's
    EXPECT_EQ(told, (std::vector<std::pair<std::uint16_t, std::uint32_t>>{{1, 0}, {8, MovingBr218}}));
    EXPECT_EQ(rig_.movement->occupantOf(0, 8), MovingBr218);
    EXPECT_EQ(rig_.movement->occupantOf(0, 1), 0u);
}

// The retired table's loop: Gleis 1, Ausfahrt Ost, Block 1..4, Einfahrt West, Gleis 1 (10,362 mm of track).
TEST_F(TrainMovementTest, RunningForwardReachesTheContactsAroundTheLoopInTheTablesOrder) {
    placeBr218(Gleis1, End::B);
    rig_.drive(MovingBr218, 1000);
    rig_.run(21s);
    EXPECT_EQ(rig_.reached(), (std::vector<std::uint16_t>{8, 3, 4, 5, 6, 7, 1}));
    const std::vector<ContactEvent> expected = {
        {1, false}, {8, true},  {8, false}, {3, true},  {3, false}, {4, true},  {4, false},
        {5, true},  {5, false}, {6, true},  {6, false}, {7, true},  {7, false}, {1, true},
    };
    EXPECT_EQ(rig_.contacts.events, expected);
    EXPECT_EQ(rig_.movement->accidents().total(), 0);
}

// A contact is occupied while any part of the train is on it: from the front's arrival until the rear has
// left, 180 mm of contact plus 200 mm of train.
TEST_F(TrainMovementTest, AContactIsOccupiedFromTheFrontsArrivalUntilTheRearLeaves) {
    placeBr218(Gleis1, End::B);
    rig_.drive(MovingBr218, 1000); // 50 mm per step
    rig_.run(1800ms);              // 900 mm: the front has just reached Ausfahrt Ost (720 + 180 over W2)
    EXPECT_FALSE(rig_.station.contact(0, 8));
    rig_.run(100ms);
    EXPECT_TRUE(rig_.station.contact(0, 8));
    EXPECT_EQ(frontBlock(), "Ausfahrt Ost");
    EXPECT_EQ(rig_.at(MovingBr218).blocks, std::vector<int>{5}) << "its rear is on W2, between the blocks";
    rig_.run(600ms); // 1,250 mm: the rear is 30 mm before the contact's end
    EXPECT_TRUE(rig_.station.contact(0, 8));
    rig_.run(100ms); // 1,300 mm: the rear has left it
    EXPECT_FALSE(rig_.station.contact(0, 8));
}

TEST_F(TrainMovementTest, BackwardRunsTheOtherWayOverW1IntoTheLine) {
    placeBr218(Gleis1, End::B);
    rig_.reverse(MovingBr218);
    rig_.drive(MovingBr218, 1000);
    rig_.run(6s);
    EXPECT_EQ(rig_.reached(), (std::vector<std::uint16_t>{7, 6}));
    EXPECT_FALSE(rig_.at(MovingBr218).headingAhead);
    EXPECT_EQ(rig_.movement->accidents().total(), 0) << "W1 lies straight for Gleis 1, trailing";
}

TEST_F(TrainMovementTest, TurningBackReturnsThroughTheBlocksItCameFrom) {
    placeBr218(Gleis1, End::B);
    rig_.drive(MovingBr218, 1000);
    rig_.run(2s); // on Ausfahrt Ost's contact
    ASSERT_EQ(rig_.reached(), std::vector<std::uint16_t>{8});
    rig_.reverse(MovingBr218);
    rig_.drive(MovingBr218, 1000);
    rig_.run(2s);
    EXPECT_EQ(rig_.contacts.events,
              (std::vector<ContactEvent>{{1, false}, {8, true}, {8, false}, {1, true}}));
    EXPECT_EQ(frontBlock(), "Gleis 1");
    EXPECT_EQ(rig_.at(MovingBr218).towards, End::A);
}

TEST_F(TrainMovementTest, SpeedZeroStopsTheTrain) {
    placeBr218(Gleis1, End::B);
    rig_.drive(MovingBr218, 500); // 250 mm/s
    rig_.run(1s);
    EXPECT_EQ(rig_.at(MovingBr218).frontMm, 790);
    rig_.drive(MovingBr218, 0);
    rig_.run(5s);
    EXPECT_EQ(rig_.at(MovingBr218).frontMm, 790);
    EXPECT_EQ(frontBlock(), "Gleis 1");
}

TEST_F(TrainMovementTest, WithoutTrackPowerNothingMoves) {
    placeBr218(Gleis1, End::B);
    rig_.drive(MovingBr218, 1000);
    rig_.station.receive(test::command(cs2::SystemStop{}));
    ASSERT_EQ(rig_.station.power(), SimulatedStation::Power::Stopped);
    rig_.run(2s);
    EXPECT_EQ(rig_.at(MovingBr218).frontMm, 540);
    EXPECT_EQ(rig_.movement->trackLoad(), 0);
}

// Facing W1 from Einfahrt West (end a): round (0) into Gleis 2, straight (1) into Gleis 1.
TEST_F(TrainMovementTest, W1DivergingLeadsIntoThePassingTrack) {
    rig_.setTurnout(1, Branch);
    placeBr218(EinfahrtWest, End::A);
    rig_.drive(MovingBr218, 1000);
    rig_.run(3s);
    EXPECT_EQ(rig_.reached(), std::vector<std::uint16_t>{2});
    EXPECT_EQ(frontBlock(), "Gleis 2");
}

TEST_F(TrainMovementTest, W1StraightLeadsIntoTheThroughTrack) {
    rig_.setTurnout(1, Straight);
    placeBr218(EinfahrtWest, End::A);
    rig_.drive(MovingBr218, 1000);
    rig_.run(3s);
    EXPECT_EQ(rig_.reached(), std::vector<std::uint16_t>{1});
    EXPECT_EQ(frontBlock(), "Gleis 1");
}

// Facing W2 from Ausfahrt Ost (end a), the way the table called "behind".
TEST_F(TrainMovementTest, W2ChoosesBetweenTheStationTracksFromTheEast) {
    rig_.setTurnout(2, Branch);
    placeBr218(AusfahrtOst, End::A);
    rig_.drive(MovingBr218, 1000);
    rig_.run(3s);
    EXPECT_EQ(rig_.reached(), std::vector<std::uint16_t>{2});
    settle(2, Straight);
    placeBr218(AusfahrtOst, End::A);
    rig_.drive(MovingBr218, 1000);
    rig_.run(3s);
    EXPECT_EQ(rig_.reached(), std::vector<std::uint16_t>{1});
}

// Facing W3 from Ausfahrt Ost (end b): straight onto the line, round into the siding.
TEST_F(TrainMovementTest, W3ChoosesBetweenTheLineAndTheSiding) {
    placeBr218(AusfahrtOst, End::B);
    rig_.drive(MovingBr218, 1000);
    rig_.run(3s);
    EXPECT_EQ(rig_.reached(), std::vector<std::uint16_t>{3});
    settle(3, Branch);
    placeBr218(AusfahrtOst, End::B);
    rig_.drive(MovingBr218, 1000);
    rig_.run(2s);
    EXPECT_EQ(rig_.reached(), std::vector<std::uint16_t>{9});
    EXPECT_EQ(frontBlock(), "Abstellgleis");
}

// A facing turnout switched after the train left its block, before its front got there, takes it the new
// way: the train follows the turnout as it lies when the front arrives.
TEST_F(TrainMovementTest, AFacingTurnoutSwitchedBeforeTheFrontArrivesTakesTheNewWay) {
    placeBr218(EinfahrtWest, End::A);
    rig_.drive(MovingBr218, 500);
    rig_.run(1400ms); // 350 mm of the 360 to W1
    rig_.setTurnout(1, Branch);
    rig_.drive(MovingBr218, 0);
    rig_.run(300ms); // W1 has settled (200 ms)
    rig_.drive(MovingBr218, 1000);
    rig_.run(2s);
    EXPECT_EQ(rig_.reached(), std::vector<std::uint16_t>{2});
    EXPECT_EQ(rig_.movement->accidents().total(), 0);
}

// The same between blocks: the way from Zufahrt passes W6 trailing and two tiles without a contact before W5
// chooses between Gerade (straight) and Abzweig (round); W5 is switched while the train is on those tiles.
TEST(TrainMovementBetweenBlocks, AFacingTurnoutAheadSwitchedWhileTheTrainIsOnTheWayTakesTheNewWay) {
    trackgraph::test::DrawnPage page(0, "Bahnhof");
    page.bufferStop(0, 1, true).contact(1, 1, 1, "Zufahrt").accessory(2, 1, "linksweiche", 1, 6);
    page.straight(3, 4, 1).accessory(5, 1, "linksweiche", 3, 5).straight(6, 6, 1).contact(7, 1, 2, "Gerade");
    page.bufferStop(8, 1, false).tile(5, 0, "bogen").contact(6, 0, 3, "Abzweig").bufferStop(7, 0, false);
    test::TrainRig rig(test::drawnLayout({page}));
    rig.place({{MovingBr218, 1, End::B}});
    rig.drive(MovingBr218, 1000);
    rig.run(500ms); // the front 250 mm beyond Zufahrt: past W6, on the first tile without a contact
    ASSERT_EQ(rig.at(MovingBr218).block, 0);
    rig.drive(MovingBr218, 0);
    rig.setTurnout(5, Branch);
    rig.run(300ms);
    rig.drive(MovingBr218, 1000);
    rig.run(1400ms); // 700 mm: over W5 round and 270 mm into Abzweig, short of its buffer stop
    EXPECT_EQ(rig.reached(), (std::vector<std::uint16_t>{1, 3}));
    EXPECT_EQ(rig.blockName(rig.at(MovingBr218).block), "Abzweig");
    EXPECT_EQ(rig.accidents, std::vector<std::string>{});
}

TEST_F(TrainMovementTest, TrackLoadGrowsWithRunningTrainsAndTheirSpeed) {
    placeBr218(Gleis1, End::B);
    const int idle = rig_.movement->trackLoad();
    EXPECT_GT(idle, 0);
    rig_.drive(MovingBr218, 300);
    rig_.run(100ms);
    const int slow = rig_.movement->trackLoad();
    rig_.drive(MovingBr218, 1000);
    rig_.run(100ms);
    EXPECT_GT(slow, idle);
    EXPECT_GT(rig_.movement->trackLoad(), slow);
}

TEST_F(TrainMovementTest, TimerMovesTrainsOnTheEventLoop) {
    TrainMovement movement(rig_.station, {{MovingBr218, Gleis1, End::B}}, {.tick = 10ms});
    movement.start();
    rig_.drive(MovingBr218, 1000);
    EXPECT_TRUE(test::waitFor([&] { return movement.position(MovingBr218)->frontMm > 600; }));
}

} // namespace
} // namespace stellwerk::sim
