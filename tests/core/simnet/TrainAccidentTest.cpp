// The accidents a real layout suffers, on the simulator's track graph: two trains touching (collision), a
// train running off the end of the track (buffer stop, open end), and a turnout run through (trailing it set
// against the train, meeting it while it moves, it moving under the train, or its way leading nowhere). Each
// is one line and one count, and stops the trains in it for good: derailed, speed 0 on the station, until
// placed again. Normal running of the demo has none.

#include "TrainTestSupport.h"
#include "sim/TrainMovement.h"

#include <gtest/gtest.h>
#include <map>
#include <string>
#include <vector>

namespace stellwerk::sim {
namespace {

using namespace std::chrono_literals;
using trackgraph::End;
using trackgraph::test::DrawnPage;

constexpr std::uint32_t CrashingBr218 = 0x4001, Ice = 0x4002, V100 = 0x0018;
constexpr std::uint8_t DivergingWay = 0;

class TrainAccidentTest : public ::testing::Test {
protected:
    std::uint16_t speedOnStation(std::uint32_t locId) const { return rig_.station.loco(locId)->speed; }

    test::TrainRig rig_{StationLayout::demo()};
};

TEST_F(TrainAccidentTest, TwoTrainsTouchingInABlockCollideAndBothStop) {
    // BR 218 from Block 1 westwards over W3 into Ausfahrt Ost, where the V 100 stands.
    rig_.place({{CrashingBr218, 3, End::A}, {V100, 8, End::B}});
    rig_.drive(CrashingBr218, 1000);
    rig_.run(4s);
    EXPECT_EQ(rig_.accidents,
              std::vector<std::string>{"collision: BR 218 Ost and V 100 2023 in block \"Ausfahrt Ost\""});
    EXPECT_EQ(rig_.movement->accidents(), (AccidentCounts{1, 0, 0}));
    EXPECT_TRUE(rig_.at(CrashingBr218).derailed);
    EXPECT_TRUE(rig_.at(V100).derailed);
    EXPECT_EQ(speedOnStation(CrashingBr218), 0) << "the station stopped it, as every controller sees";
    // Derailed trains stay where they are and cause nothing more, whatever they are told.
    const int front = rig_.at(CrashingBr218).frontMm;
    rig_.drive(CrashingBr218, 1000);
    rig_.drive(V100, 1000);
    rig_.run(3s);
    EXPECT_EQ(rig_.at(CrashingBr218).frontMm, front);
    EXPECT_EQ(rig_.movement->accidents().total(), 1);
}

TEST_F(TrainAccidentTest, ARunningTrainIntoADerailedOneIsAnotherCollision) {
    rig_.place({{CrashingBr218, 3, End::A}, {V100, 8, End::B}, {Ice, 4, End::A}});
    rig_.drive(CrashingBr218, 1000);
    rig_.run(4s);
    ASSERT_EQ(rig_.movement->accidents().collisions, 1);
    rig_.drive(Ice, 1000); // from Block 2 westwards through Block 1 to W3
    rig_.run(6s);
    EXPECT_EQ(rig_.movement->accidents().collisions, 2);
    // The BR 218 stopped with its rear still on W3, between Block 1 and Ausfahrt Ost.
    EXPECT_EQ(rig_.accidents.back(),
              "collision: BR 218 Ost and ICE 3 Velaro on turnout 3 (page 'Bahnhof', column 15, row 5)");
    EXPECT_TRUE(rig_.at(Ice).derailed);
}

TEST_F(TrainAccidentTest, PlacedAgainADerailedTrainRunsAgain) {
    rig_.place({{CrashingBr218, 3, End::A}, {V100, 8, End::B}});
    rig_.drive(CrashingBr218, 1000);
    rig_.run(4s);
    ASSERT_TRUE(rig_.at(CrashingBr218).derailed);
    ASSERT_EQ(rig_.movement->place({CrashingBr218, 1, End::B}), std::nullopt);
    EXPECT_FALSE(rig_.at(CrashingBr218).derailed);
    rig_.drive(CrashingBr218, 1000);
    rig_.run(1s);
    EXPECT_EQ(rig_.at(CrashingBr218).frontMm, 1040);
}

// Through W3 round into the Abstellgleis, on into the Bw with W4 straight, to Lokschuppen 2's buffer stop.
TEST_F(TrainAccidentTest, RunningIntoABufferStopDerailsTheTrain) {
    rig_.place({{CrashingBr218, 9, End::B}});
    rig_.drive(CrashingBr218, 1000);
    rig_.run(6s);
    EXPECT_EQ(rig_.accidents,
              std::vector<std::string>{"buffer stop: BR 218 Ost ran into the buffer stop beyond "
                                       "block \"Abstellgleis\" (page 'Bw', column 10, row 2)"});
    EXPECT_EQ(rig_.movement->accidents(), (AccidentCounts{0, 1, 0}));
    EXPECT_TRUE(rig_.at(CrashingBr218).derailed);
    EXPECT_EQ(speedOnStation(CrashingBr218), 0);
    rig_.run(2s);
    EXPECT_EQ(rig_.movement->accidents().total(), 1) << "it does not run into it again";
}

TEST_F(TrainAccidentTest, RunningOffAnOpenEndIsABufferStopAccident) {
    DrawnPage page(0, "Test");
    page.bufferStop(0, 0, true)
        .contact(1, 0, 1, "Gleis")
        .straight(2, 3, 0); // the track ends east of column 3
    test::TrainRig rig(test::drawnLayout({page}));
    rig.place({{CrashingBr218, 1, End::B}});
    rig.drive(CrashingBr218, 1000);
    rig.run(2s);
    EXPECT_EQ(rig.accidents,
              std::vector<std::string>{"buffer stop: mfx:1 ran off the open end of the track "
                                       "beyond block \"Gleis\" (page 'Test', column 3, row 0)"});
    EXPECT_EQ(rig.movement->accidents().bufferStops, 1);
}

// Out of Gleis 1 eastwards W2 is passed trailing on its straight leg: set round for Gleis 2, it is run
// through.
TEST_F(TrainAccidentTest, TrailingThroughATurnoutSetAgainstTheTrain) {
    rig_.setTurnout(2, DivergingWay);
    rig_.place({{CrashingBr218, 1, End::B}});
    rig_.drive(CrashingBr218, 1000);
    rig_.run(3s);
    EXPECT_EQ(rig_.accidents,
              std::vector<std::string>{"turnout run through: BR 218 Ost ran through turnout 2 "
                                       "set against it (page 'Bahnhof', column 12, row 5)"});
    EXPECT_EQ(rig_.movement->accidents(), (AccidentCounts{0, 0, 1}));
    EXPECT_TRUE(rig_.at(CrashingBr218).derailed);
}

// W1 switched when the front is 10 mm before it: it moves for 200 ms (magnetartikel.cs2 names no time).
TEST_F(TrainAccidentTest, MeetingATurnoutWhileItMoves) {
    rig_.place({{CrashingBr218, 7, End::A}});
    rig_.drive(CrashingBr218, 1000);
    rig_.run(700ms); // 350 of the 360 mm to W1
    rig_.setTurnout(1, DivergingWay);
    rig_.run(100ms);
    EXPECT_EQ(rig_.accidents,
              std::vector<std::string>{"turnout run through: BR 218 Ost ran into turnout 1 "
                                       "while it was moving (page 'Bahnhof', column 4, row 5)"});
    EXPECT_EQ(rig_.movement->accidents().turnoutsRunThrough, 1);
}

TEST_F(TrainAccidentTest, ATurnoutSwitchedUnderTheTrain) {
    rig_.place({{CrashingBr218, 7, End::A}});
    rig_.drive(CrashingBr218, 1000);
    rig_.run(800ms); // the front 40 mm onto W1
    ASSERT_EQ(rig_.accidents, std::vector<std::string>{});
    rig_.setTurnout(1, DivergingWay);
    rig_.run(100ms);
    EXPECT_EQ(rig_.accidents,
              std::vector<std::string>{"turnout run through: turnout 1 moved under BR 218 Ost "
                                       "(page 'Bahnhof', column 4, row 5)"});
    EXPECT_TRUE(rig_.at(CrashingBr218).derailed);
}

TEST_F(TrainAccidentTest, ATurnoutSwitchedAfterTheTrainLeftItIsNoAccident) {
    rig_.place({{CrashingBr218, 7, End::A}});
    rig_.drive(CrashingBr218, 1000);
    rig_.run(2s); // the rear is 480 mm past W1, in Gleis 1
    rig_.setTurnout(1, DivergingWay);
    rig_.run(1s);
    EXPECT_EQ(rig_.movement->accidents().total(), 0);
}

// Turnout 5's diverging leg leads nowhere: the fan of the track graph tests without its branch.
TEST_F(TrainAccidentTest, ATurnoutWayLeadingNowhere) {
    DrawnPage page(0, "Test");
    page.bufferStop(0, 1, true).contact(1, 1, 1, "Zufahrt").accessory(2, 1, "linksweiche", 3, 5);
    page.straight(3, 3, 1).contact(4, 1, 2, "Gerade").bufferStop(5, 1, false);
    test::TrainRig rig(test::drawnLayout({page}, test::locomotivesFile({{CrashingBr218, "BR 218 Ost"}})));
    rig.setTurnout(5, DivergingWay);
    rig.place({{CrashingBr218, 1, End::B}});
    rig.drive(CrashingBr218, 1000);
    rig.run(2s);
    EXPECT_EQ(rig.accidents,
              std::vector<std::string>{"turnout run through: BR 218 Ost left turnout 5 where its "
                                       "way leads nowhere (page 'Test', column 2, row 1)"});
    EXPECT_EQ(rig.movement->accidents().turnoutsRunThrough, 1);
}

// The embedded demo as the app starts it: BR 218 Ost and ICE 3 Velaro round the loop at speed 600, the V 100
// and the Köf standing; five simulated minutes without an accident, every contact of the loop passed.
TEST_F(TrainAccidentTest, TheDemoRunsForMinutesWithoutAnAccident) {
    rig_.place(demoPlacements());
    rig_.drive(CrashingBr218, 600);
    rig_.drive(Ice, 600);
    rig_.contacts.events.clear();
    rig_.run(5min);
    EXPECT_EQ(rig_.movement->accidents().total(), 0) << ::testing::PrintToString(rig_.accidents);
    std::map<std::uint16_t, int> passes;
    for (const std::uint16_t contact : rig_.reached())
        ++passes[contact];
    for (const std::uint16_t contact : {1, 8, 3, 4, 5, 6, 7})
        EXPECT_GE(passes[contact], 15) << "contact " << contact; // 300 mm/s round 10.4 m: 8.7 rounds each
    EXPECT_EQ(passes.count(2), 0U);
    EXPECT_TRUE(rig_.station.contact(0, 2)) << "the V 100 still stands on Gleis 2";
    EXPECT_TRUE(rig_.station.contact(0, 9)) << "the Köf still stands on the Abstellgleis";
}

} // namespace
} // namespace stellwerk::sim
