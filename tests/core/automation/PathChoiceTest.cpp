// PathChoice on the demo's graph: the nearest station block, never into a block shorter than the train, never
// through an occupied one, and no way that leaves two trains facing each other on a single line.
#include "automation/PathChoice.h"

#include "AutomationTestSupport.h"

#include <set>

namespace stellwerk::automation {
namespace {

using namespace test;
using trackgraph::End;

// Every block free but `taken`; `facing` says which end a train in a block faces.
TrackState stateWith(std::set<int> taken, std::map<int, End> facing = {}) {
    TrackState state;
    state.blockFree = [taken](int block) { return !taken.contains(block); };
    state.connectionFree = [](int) { return true; };
    state.trainFacing = [facing](int block) -> std::optional<End> {
        const auto found = facing.find(block);
        return found == facing.end() ? std::nullopt : std::optional<End>(found->second);
    };
    return state;
}

TEST(PathChoice, ThePlainBlockAheadIsPassedForTheNearestStationBlock) {
    const PathChoice choice(demo());
    const std::optional<Path> path = choice.choose({Gleis1, End::B}, 200, stateWith({}));
    ASSERT_TRUE(path.has_value());
    EXPECT_EQ(path->blocks, (std::vector<int>{AusfahrtOst, Block1})); // Block 1 has signal F facing the train
    EXPECT_EQ(path->connections, (std::vector<int>{8, 12}));
    EXPECT_EQ(path->turnouts, (std::vector<std::pair<std::int64_t, int>>{{2, 1}, {3, 1}}));
    EXPECT_TRUE(choice.isStation(Block1, End::B));
    EXPECT_FALSE(choice.isStation(AusfahrtOst, End::B));
    EXPECT_TRUE(choice.isStation(Gleis1, End::A)); // by its name
}

TEST(PathChoice, NeverIntoABlockShorterThanTheTrainNorThroughAnOccupiedOne) {
    const PathChoice choice(demo());
    // Ausfahrt Ost is 360 mm long; Block 1 beyond it is taken.
    const std::optional<Path> short_ = choice.choose({Gleis1, End::B}, 300, stateWith({Block1}));
    ASSERT_TRUE(short_.has_value());
    EXPECT_EQ(short_->blocks, std::vector<int>{AusfahrtOst});
    EXPECT_FALSE(choice.choose({Gleis1, End::B}, 400, stateWith({Block1})).has_value());
}

TEST(PathChoice, NeverIntoABlockThatCannotBeLeftForwards) {
    const PathChoice choice(demo());
    // From Ausfahrt Ost towards a: Gleis 1 and Gleis 2 lead on; towards b the Abstellgleis does not.
    const std::optional<Path> path = choice.choose({AusfahrtOst, End::B}, 200, stateWith({Block1}));
    EXPECT_FALSE(path.has_value()) << "the Abstellgleis ends at the depot: a train there could not go on";
}

TEST(PathChoice, TwoTrainsFacingEachOtherOnTheSingleLineAreNotLetIn) {
    const PathChoice choice(demo());
    // A train in Block 3 faces end a, towards Block 2: Block 2 would be a dead end for a train from Block 1.
    EXPECT_FALSE(choice.choose({Block1, End::B}, 200, stateWith({Block3}, {{Block3, End::A}})).has_value());
    // The same train facing away (end b) moves on: Block 2 is a fine stop.
    const std::optional<Path> behind =
        choice.choose({Block1, End::B}, 200, stateWith({Block3}, {{Block3, End::B}}));
    ASSERT_TRUE(behind.has_value());
    EXPECT_EQ(behind->blocks, std::vector<int>{Block2});
}

// The single line from Ausfahrt Ost to Einfahrt West has its place to pass only in the station (the siding
// off Ausfahrt Ost does not count: it ends at buffer stops). A train from Gleis 1 runs it clockwise: towards
// end b in Block 3, towards end a in Block 4. A train in Block 4 facing b comes the other way: the train on
// Gleis 1 is kept out of the whole line, not even into Ausfahrt Ost, or both would wait for ever.
TEST(PathChoice, NoTrainEntersTheSingleLineWhileAnotherComesTheOtherWay) {
    const PathChoice choice(demo());
    TrackState state = stateWith({Block4}, {{Block4, End::B}});
    state.travelling = [](int block) -> std::optional<End> {
        return block == Block4 ? std::optional<End>(End::B) : std::nullopt;
    };
    EXPECT_FALSE(choice.choose({Gleis1, End::B}, 200, state).has_value());
    // A way reserved the same way through Block 3 (towards b) is no obstacle; the other way it is.
    state = stateWith({Block3});
    state.travelling = [](int block) -> std::optional<End> {
        return block == Block3 ? std::optional<End>(End::B) : std::nullopt;
    };
    const std::optional<Path> following = choice.choose({Gleis1, End::B}, 200, state);
    ASSERT_TRUE(following.has_value());
    EXPECT_EQ(following->destination(), Block1);
    state.travelling = [](int block) -> std::optional<End> {
        return block == Block3 ? std::optional<End>(End::A) : std::nullopt;
    };
    EXPECT_FALSE(choice.choose({Gleis1, End::B}, 200, state).has_value());
}

} // namespace
} // namespace stellwerk::automation
