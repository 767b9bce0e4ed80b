// Reservations: a way is reserved whole or not at all, conflicting connections never belong to two trains.
#include "automation/Reservations.h"

#include "AutomationTestSupport.h"

namespace stellwerk::automation {
namespace {

using namespace test;

// Connections of the demo: 8 Gleis 1 b -> Ausfahrt Ost (turnout 2 straight), 9 Ausfahrt Ost a -> Gleis 2 b
// (turnout 2 diverging), 12 Ausfahrt Ost b -> Block 1 (turnout 3 straight).
Path wayOf(std::vector<int> connections, std::vector<int> blocks) {
    return Path{std::move(connections), std::move(blocks), {}};
}

TEST(Reservations, AWayIsReservedWholeOrNotAtAll) {
    Reservations reservations(demo());
    ASSERT_TRUE(reservations.holdBlock(1, Block1));
    EXPECT_FALSE(reservations.reserve(2, wayOf({8, 12}, {AusfahrtOst, Block1})));
    EXPECT_EQ(reservations.blockOwner(AusfahrtOst), 0u);
    EXPECT_EQ(reservations.connectionOwner(8), 0u);
    EXPECT_TRUE(reservations.reserve(2, wayOf({8}, {AusfahrtOst})));
    EXPECT_EQ(reservations.blockOwner(AusfahrtOst), 2u);
    EXPECT_EQ(reservations.connectionOwner(8), 2u);
}

TEST(Reservations, ATurnoutBelongsToTheTrainWhoseWayPassesItAndConflictingWaysAreRefused) {
    Reservations reservations(demo());
    ASSERT_TRUE(reservations.reserve(1, wayOf({8}, {AusfahrtOst})));
    EXPECT_EQ(reservations.turnoutOwner(2), std::make_optional(std::make_pair(1u, 1)));
    EXPECT_FALSE(reservations.connectionAvailable(9, 2)); // turnout 2 diverging, over the same tile
    EXPECT_FALSE(reservations.reserve(2, wayOf({9}, {Gleis2})));
    EXPECT_TRUE(reservations.connectionAvailable(9, 1));
    reservations.releaseConnection(1, 8);
    EXPECT_FALSE(reservations.turnoutOwner(2).has_value());
    EXPECT_TRUE(reservations.reserve(2, wayOf({9}, {Gleis2})));
}

TEST(Reservations, GivingBackKeepsWhatTheTrainStandsOn) {
    Reservations reservations(demo());
    ASSERT_TRUE(reservations.holdBlock(1, Gleis1));
    ASSERT_TRUE(reservations.reserve(1, wayOf({8, 12}, {AusfahrtOst, Block1})));
    reservations.releaseAllBut(1, {Gleis1}, {});
    EXPECT_EQ(reservations.blocksOf(1), std::vector<int>{Gleis1});
    EXPECT_TRUE(reservations.connectionsOf(1).empty());
}

} // namespace
} // namespace stellwerk::automation
