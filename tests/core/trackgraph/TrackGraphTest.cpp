// Blocks, connections and problems of pages drawn in the tests, one rule of docs/guide/track-graph.md each.
#include "TrackGraphTestSupport.h"
#include "trackgraph/GraphReport.h"

#include <algorithm>
#include <set>

using namespace stellwerk;
using namespace stellwerk::trackgraph;
using namespace stellwerk::trackgraph::test;

namespace {

// A line from a buffer stop to a buffer stop: contact 1 at column 1, contact 2 at `secondColumn`, plain track
// between them, and at column 3 a signal turned by `signalRotation` (none when negative).
DrawnPage lineWithTwoContacts(int secondColumn, int signalRotation = -1) {
    DrawnPage page(0, "Strecke");
    page.bufferStop(0, 0, true).contact(1, 0, 1, "Gleis A");
    for (int column = 2; column < secondColumn; ++column)
        if (column == 3 && signalRotation >= 0)
            page.accessory(column, 0, "signal", signalRotation, 10, signalRotation == 0 ? "S1" : "S2");
        else
            page.tile(column, 0, "gerade");
    page.contact(secondColumn, 0, 2).bufferStop(secondColumn + 1, 0, false);
    return page;
}

std::vector<int> columnsOf(const TrackGraph& graph, const Block& block) {
    std::vector<int> columns;
    for (const TileId tile : block.tiles)
        columns.push_back(graph.tile(tile).place.column);
    return columns;
}

// Contact 1 west of a left turnout (keyboard 5) whose points face it; straight on to contact 2, diverging
// north and round to contact 3. Blocks by end a: 1 = contact 3 (row 0), 2 = contact 1, 3 = contact 2.
DrawnPage turnoutFan() {
    DrawnPage page(0, "Bahnhof");
    page.bufferStop(0, 1, true).contact(1, 1, 1, "Zufahrt").accessory(2, 1, "linksweiche", 3, 5, "W5");
    page.straight(3, 3, 1).contact(4, 1, 2, "Gerade").bufferStop(5, 1, false);
    page.tile(2, 0, "bogen").contact(3, 0, 3, "Abzweig").bufferStop(4, 0, false);
    return page;
}

PositionOf positions(std::map<std::int64_t, int> set) {
    return [set](std::int64_t article) -> std::optional<int> {
        const auto found = set.find(article);
        return found == set.end() ? std::nullopt : std::optional(found->second);
    };
}

} // namespace

TEST(TrackGraph, ASignalBetweenTwoContactsEndsTheBlockItHoldsTrainsIn) {
    const TrackGraph graph = derived({lineWithTwoContacts(5, 0)}); // the signal faces trains from contact 1
    ASSERT_EQ(graph.blocks().size(), 2U);
    const Block& first = graph.block(1);
    EXPECT_EQ(first.name, "Gleis A");
    EXPECT_EQ(columnsOf(graph, first), (std::vector<int>{0, 1, 2, 3}));
    ASSERT_EQ(first.signalsAlong.size(), 1U);
    EXPECT_EQ(first.signalsAlong[0].name, "S1");
    EXPECT_EQ(first.signalsAlong[0].towards, End::B);
    EXPECT_EQ(columnsOf(graph, graph.block(2)), (std::vector<int>{4, 5, 6}));
    EXPECT_EQ(graph.block(2).name, "Block 2");
}

TEST(TrackGraph, ASignalFacingTheOtherWayBelongsToTheLaterBlock) {
    const TrackGraph graph = derived({lineWithTwoContacts(5, 2)}); // the signal faces trains from contact 2
    EXPECT_EQ(columnsOf(graph, graph.block(1)), (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(columnsOf(graph, graph.block(2)), (std::vector<int>{3, 4, 5, 6}));
    ASSERT_EQ(graph.block(2).signalsAlong.size(), 1U);
    EXPECT_EQ(graph.block(2).signalsAlong[0].towards, End::A);
    EXPECT_EQ(graph.block(2).name, "S2"); // no label on its contact: the signal names it
}

TEST(TrackGraph, WithoutASignalTwoContactsShareTheTrackBetweenThemHalfway) {
    const TrackGraph graph = derived({lineWithTwoContacts(6)});
    EXPECT_EQ(columnsOf(graph, graph.block(1)), (std::vector<int>{0, 1, 2, 3}));
    EXPECT_EQ(columnsOf(graph, graph.block(2)), (std::vector<int>{4, 5, 6, 7}));
    // They meet right there: a connection over no tile each way.
    EXPECT_EQ(waysFrom(graph, {1, End::B}), std::vector<std::string>{"2a"});
    EXPECT_EQ(waysFrom(graph, {2, End::A}), std::vector<std::string>{"1b"});
    EXPECT_TRUE(graph.connection(1).path.empty());
    EXPECT_EQ(graph.block(1).end(End::B).beyond, EndKind::Block);
    EXPECT_EQ(graph.block(1).end(End::A).beyond, EndKind::BufferStop);
    EXPECT_TRUE(graph.problems().empty());
}

TEST(TrackGraph, ContactsDrawnSideBySideAreOneBlockInOrderAlongTheTrack) {
    DrawnPage page(0, "Strecke");
    page.bufferStop(0, 0, true).contact(1, 0, 1).contact(2, 0, 2, "Halt").bufferStop(3, 0, false);
    const TrackGraph graph = derived({page});
    ASSERT_EQ(graph.blocks().size(), 1U);
    const Block& block = graph.block(1);
    EXPECT_EQ(contactNumbers(block), (std::vector<std::int64_t>{1, 2}));
    EXPECT_EQ(block.name, "Halt");
    EXPECT_EQ(block.contacts[0].fromMm, 90);
    EXPECT_EQ(block.contacts[0].toMm, 270);
    EXPECT_EQ(block.contacts[1].fromMm, 270);
    EXPECT_EQ(block.contacts[1].toMm, 450);
    EXPECT_EQ(block.lengthMm, 90 + 180 + 180 + 90);
    EXPECT_EQ(block.lengthTiles(), 4);
    EXPECT_EQ(block.end(End::A).port, Port::End); // the buffer stop at column 0
}

TEST(TrackGraph, EndAIsTheEndWhoseTileComesFirstInPageRowColumnOrder) {
    DrawnPage page(0, "Strecke");
    // A line running north-south: end a is at the top.
    page.tile(4, 1, "prellbock", 1)
        .contact(4, 2, 7, "", 1)
        .tile(4, 3, "gerade", 1)
        .tile(4, 4, "prellbock", 3);
    const TrackGraph graph = derived({page});
    ASSERT_EQ(graph.blocks().size(), 1U);
    EXPECT_EQ(placeOf(graph, graph.block(1).end(End::A).tile), (TilePlace{0, 4, 1}));
    EXPECT_EQ(placeOf(graph, graph.block(1).end(End::B).tile), (TilePlace{0, 4, 4}));
    EXPECT_EQ(graph.block(1).path.front().tile, graph.block(1).end(End::A).tile);
}

TEST(TrackGraph, ATurnoutsLegsLeadToTheirBlocksWithThePositionTheyNeed) {
    const TrackGraph graph = derived({turnoutFan()});
    ASSERT_EQ(graph.blocks().size(), 3U);
    EXPECT_EQ(graph.block(1).name, "Abzweig");
    EXPECT_EQ(graph.block(2).name, "Zufahrt");
    EXPECT_EQ(graph.block(3).name, "Gerade");
    EXPECT_EQ(waysFrom(graph, {2, End::B}), (std::vector<std::string>{"1a 5:diverging", "3a 5:straight"}));
    EXPECT_EQ(waysFrom(graph, {3, End::A}), std::vector<std::string>{"2b 5:straight"});
    EXPECT_EQ(waysFrom(graph, {1, End::A}), std::vector<std::string>{"2b 5:diverging"});
    EXPECT_TRUE(waysFrom(graph, {2, End::A}).empty());
    for (const Connection& connection : graph.connections()) {
        ASSERT_EQ(connection.turnouts.size(), 1U);
        EXPECT_EQ(connection.turnouts[0].facing, connection.from.block == 2);
        // Every way over W5 conflicts with the three others.
        EXPECT_EQ(connection.conflicts.size(), 3U);
    }
    EXPECT_TRUE(graph.problems().empty());
}

TEST(TrackGraph, FollowingTheTrackOverATurnout) {
    const TrackGraph graph = derived({turnoutFan()});
    EXPECT_EQ(graph.follow({2, End::B}, positions({{5, 1}})).reached, (BlockEnd{3, End::A}));
    EXPECT_EQ(graph.follow({2, End::B}, positions({{5, 0}})).reached, (BlockEnd{1, End::A}));
    EXPECT_EQ(graph.follow({2, End::B}, positions({})).kind, LeadKind::NotSet);
    const Lead against = graph.follow({3, End::A}, positions({{5, 0}}));
    EXPECT_EQ(against.kind, LeadKind::SetAgainst);
    EXPECT_EQ(against.article, 5);
    EXPECT_FALSE(against.facing); // trailing through it
    EXPECT_TRUE(graph.follow({2, End::B}, positions({})).facing);
    EXPECT_EQ(placeOf(graph, *against.turnout), (TilePlace{0, 2, 1}));
    EXPECT_EQ(graph.follow({2, End::A}, positions({})).kind, LeadKind::BufferStop);
}

TEST(TrackGraph, AThreeWayTurnoutNamesLeftStraightAndRight) {
    DrawnPage page(0, "Bw");
    page.bufferStop(0, 1, true).contact(1, 1, 1).accessory(2, 1, "dreiwegweiche", 3, 7);
    page.tile(2, 0, "bogen").contact(3, 0, 2).bufferStop(4, 0, false);
    page.contact(3, 1, 3).bufferStop(4, 1, false);
    page.tile(2, 2, "bogen", 1).contact(3, 2, 4).bufferStop(4, 2, false);
    const TrackGraph graph = derived({page});
    const int from = *graph.blockWithContact({0, 1});
    std::set<std::string> ways;
    for (const int id : graph.connectionsFrom({from, End::B})) {
        const Connection& connection = graph.connection(id);
        ways.insert(std::to_string(contactNumbers(graph.block(connection.to.block))[0]) + " " +
                    std::string(positionName(connection.turnouts[0].kind, connection.turnouts[0].position)));
    }
    EXPECT_EQ(ways, (std::set<std::string>{"2 left", "3 straight", "4 right"}));
}

TEST(TrackGraph, ADoubleSlipJoinsFourTracksOverItsStraightAndCurvedLegs) {
    for (const std::string type : {"dkweiche", "dkweiche_2"}) {
        DrawnPage page(0, "Bahnhof");
        page.tile(2, 0, "prellbock", 1).contact(2, 1, 3, "Nord", 1);
        page.tile(0, 2, "prellbock", 2).contact(1, 2, 1, "West").accessory(2, 2, type, 0, 9);
        page.contact(3, 2, 2, "Ost").tile(4, 2, "prellbock");
        page.contact(2, 3, 4, "Sued", 1).tile(2, 4, "prellbock", 3);
        const TrackGraph graph = derived({page});
        const auto ways = [&graph](std::int64_t contact) {
            const Block& block = graph.block(*graph.blockWithContact({0, contact}));
            std::set<std::string> names;
            for (const End end : {End::A, End::B})
                for (const int id : graph.connectionsFrom({block.id, end})) {
                    const Connection& c = graph.connection(id);
                    names.insert(graph.block(c.to.block).name + " " +
                                 std::string(positionName(c.turnouts[0].kind, c.turnouts[0].position)));
                }
            return names;
        };
        EXPECT_EQ(ways(1), (std::set<std::string>{"Ost straight", "Sued diverging"})) << type;
        EXPECT_EQ(ways(3), (std::set<std::string>{"Sued straight", "Ost diverging"})) << type;
    }
}

TEST(TrackGraph, ATwoDriveSlipInAMixedPositionSendsTheTrainStraightWhereBothLegsAreSet) {
    DrawnPage page(0, "Bahnhof");
    page.tile(2, 0, "prellbock", 1).contact(2, 1, 3, "Nord", 1);
    page.tile(0, 2, "prellbock", 2).contact(1, 2, 1, "West").accessory(2, 2, "dkweiche_2", 0, 9);
    page.contact(3, 2, 2, "Ost").tile(4, 2, "prellbock");
    page.contact(2, 3, 4, "Sued", 1).tile(2, 4, "prellbock", 3);
    const TrackGraph graph = derived({page});
    const int west = *graph.blockWithContact({0, 1});
    const End towardsSlip = graph.block(west).end(End::B).beyond == EndKind::Junction ? End::B : End::A;
    const Lead lead = graph.follow({west, towardsSlip}, positions({{9, 2}}));
    EXPECT_EQ(graph.block(lead.reached.block).name, "Ost");
    EXPECT_EQ(graph.follow({west, towardsSlip}, positions({{9, 3}})).kind, LeadKind::SetAgainst);
}

TEST(TrackGraph, ACrossingJoinsNothingButConnectionsOverItConflict) {
    DrawnPage page(0, "Kreuz");
    page.tile(0, 2, "prellbock", 2)
        .contact(1, 2, 1)
        .tile(2, 2, "kreuzung")
        .contact(3, 2, 2)
        .tile(4, 2, "prellbock");
    page.tile(2, 0, "prellbock", 1)
        .contact(2, 1, 3, "", 1)
        .contact(2, 3, 4, "", 1)
        .tile(2, 4, "prellbock", 3);
    const TrackGraph graph = derived({page});
    ASSERT_EQ(graph.blocks().size(), 4U);
    ASSERT_EQ(graph.connections().size(), 4U); // 1 <-> 2, 3 <-> 4
    for (const Connection& connection : graph.connections()) {
        ASSERT_EQ(connection.crossings.size(), 1U);
        EXPECT_EQ(placeOf(graph, connection.crossings[0]), (TilePlace{0, 2, 2}));
        EXPECT_TRUE(connection.turnouts.empty());
        EXPECT_EQ(connection.conflicts.size(), 3U);
    }
}

TEST(TrackGraph, AnUnderpassCarriesTwoBlocksThatNeverConflict) {
    DrawnPage page(0, "Bruecke");
    page.tile(0, 2, "prellbock", 2)
        .contact(1, 2, 1)
        .tile(2, 2, "unterfuehrung")
        .contact(3, 2, 2)
        .tile(4, 2, "prellbock");
    page.tile(2, 0, "prellbock", 1)
        .contact(2, 1, 3, "", 1)
        .contact(2, 3, 4, "", 1)
        .tile(2, 4, "prellbock", 3);
    const TrackGraph graph = derived({page});
    const std::vector<int> blocks = graph.blocksAt(*graph.tileAt({0, 2, 2}));
    ASSERT_EQ(blocks.size(), 2U);
    EXPECT_EQ(std::set<int>(blocks.begin(), blocks.end()),
              (std::set<int>{*graph.blockWithContact({0, 1}), *graph.blockWithContact({0, 3})}));
    for (const Connection& connection : graph.connections()) {
        EXPECT_TRUE(connection.crossings.empty());
        EXPECT_TRUE(connection.conflicts.empty());
    }
}

TEST(TrackGraph, ALoopWithTwoContactsIsTwoBlocksLeadingIntoEachOther) {
    DrawnPage page(0, "Kreis");
    page.tile(0, 0, "s88bogen", 0, 1)
        .tile(1, 0, "bogen", 3)
        .tile(1, 1, "s88bogen", 2, 2)
        .tile(0, 1, "bogen", 1);
    const TrackGraph graph = derived({page});
    ASSERT_EQ(graph.blocks().size(), 2U);
    for (const End end : {End::A, End::B}) {
        ASSERT_EQ(graph.connectionsFrom({1, end}).size(), 1U);
        EXPECT_EQ(graph.connection(graph.connectionsFrom({1, end})[0]).to.block, 2);
    }
    EXPECT_TRUE(graph.problems().empty());
}

TEST(TrackGraph, ALoopWithOneContactLeadsBackIntoItself) {
    DrawnPage page(0, "Kreis");
    page.tile(0, 0, "s88bogen", 0, 1).tile(1, 0, "bogen", 3).tile(1, 1, "bogen", 2).tile(0, 1, "bogen", 1);
    const TrackGraph graph = derived({page});
    ASSERT_EQ(graph.blocks().size(), 1U);
    EXPECT_EQ(graph.block(1).lengthTiles(), 4);
    EXPECT_EQ(waysFrom(graph, {1, End::B}), std::vector<std::string>{"1a"});
    EXPECT_EQ(waysFrom(graph, {1, End::A}), std::vector<std::string>{"1b"});
}

TEST(TrackGraph, TrackWithoutAContactBetweenTwoBlocksIsPartOfTheirConnectionAndReported) {
    DrawnPage fixed(0, "Bahnhof");
    fixed.bufferStop(0, 1, true).contact(1, 1, 1, "Zufahrt").accessory(2, 1, "linksweiche", 3, 5, "W5");
    fixed.straight(3, 4, 1)
        .accessory(5, 1, "linksweiche", 1, 6)
        .contact(6, 1, 2, "Gerade")
        .bufferStop(7, 1, false);
    fixed.tile(2, 0, "bogen").contact(3, 0, 3, "Abzweig").bufferStop(4, 0, false);
    const TrackGraph graph = derived({fixed});
    // W5 straight, two tiles without contact, then W6 passed trailing on its straight leg.
    const int zufahrt = *graph.blockWithContact({0, 1});
    const int gerade = *graph.blockWithContact({0, 2});
    bool found = false;
    for (const Connection& connection : graph.connections())
        if (connection.from.block == zufahrt && connection.to.block == gerade) {
            found = true;
            EXPECT_EQ(connection.path.size(), 4U);
            EXPECT_EQ(connection.lengthMm, 4 * 180);
            ASSERT_EQ(connection.turnouts.size(), 2U);
            EXPECT_EQ(connection.turnouts[1].article, 6);
            EXPECT_FALSE(connection.turnouts[1].facing);
        }
    EXPECT_TRUE(found);
    EXPECT_EQ(countProblems(graph, ProblemKind::NoContact), 1U);
    EXPECT_EQ(countProblems(graph, ProblemKind::TurnoutLegNowhere), 1U); // W6's diverging leg
    for (const Problem& problem : graph.problems()) {
        if (problem.kind == ProblemKind::NoContact) {
            EXPECT_EQ(problem.text,
                      "These 2 tiles of track between turnout 5 and turnout 6 have no contact, so a "
                      "train there cannot be seen; add a contact where trains may stop.");
        }
    }
}

TEST(TrackGraph, AWayThatNeedsOneTurnoutInTwoPositionsIsLeftOutAndReported) {
    // Keyboard 5 drawn twice: its straight leg at column 2 leads into its diverging leg at column 4.
    DrawnPage page(0, "Fehler");
    page.bufferStop(0, 1, true).contact(1, 1, 1).accessory(2, 1, "rechtsweiche", 3, 5).straight(3, 3, 1);
    page.accessory(4, 1, "linksweiche", 0, 5).contact(4, 2, 2, "", 1).tile(4, 3, "prellbock", 3);
    const TrackGraph graph = derived({page});
    EXPECT_TRUE(graph.connections().empty());
    // Found from both blocks: where each way meets the second drawing.
    std::vector<int> columns;
    for (const Problem& problem : graph.problems())
        if (problem.kind == ProblemKind::TurnoutClash)
            columns.push_back(placeOf(graph, problem.tile).column);
    EXPECT_EQ(columns, (std::vector<int>{2, 4}));
}

TEST(TrackGraph, TooManyWaysFromOneEndAreCutShortAndSaidSo) {
    // A yard ladder: 70 turnouts in a row, each leading down into a siding with its own contact.
    DrawnPage page(0, "Ladder");
    page.bufferStop(0, 0, true).contact(1, 0, 1);
    for (int column = 2; column < 72; ++column) {
        page.accessory(column, 0, "rechtsweiche", 3, column);
        page.contact(column, 1, 100 + column, "", 1).tile(column, 2, "prellbock", 3);
    }
    page.bufferStop(72, 0, false);
    const TrackGraph graph = derived({page});
    EXPECT_EQ(graph.connectionsFrom({*graph.blockWithContact({0, 1}), End::B}).size(), 64U);
    EXPECT_EQ(countProblems(graph, ProblemKind::TooManyWays), 1U);
}

TEST(TrackGraph, ATrackEndingAtATurntableIsNoOpenEnd) {
    DrawnPage page(0, "Bw");
    page.bufferStop(0, 0, true).contact(1, 0, 1).tile(2, 0, "drehscheibe_dig_3");
    const TrackGraph graph = derived({page});
    ASSERT_EQ(graph.blocks().size(), 1U);
    EXPECT_EQ(graph.block(1).end(End::B).beyond, EndKind::Turntable);
    EXPECT_TRUE(graph.problems().empty());
    EXPECT_EQ(graph.follow({1, End::B}, positions({})).kind, LeadKind::Turntable);
}

TEST(TrackGraph, LooseEndsAreReportedWhereTheyAre) {
    DrawnPage page(0, "Baustelle");
    page.contact(1, 0, 1).straight(2, 2, 0);                      // open at both ends
    page.tile(5, 0, "gerade");                                    // alone
    page.accessory(1, 2, "rechtsweiche", 3, 4).straight(2, 2, 2); // points open, diverging leg open
    page.tile(3, 2, "bogen", 2);                                  // turns north, where nothing goes on
    page.tile(0, 2, "gerade", 1); // runs north-south beside the points: no joint
    const TrackGraph graph = derived({page});
    std::vector<std::string> found;
    for (const Problem& problem : graph.problems()) {
        const TilePlace place = placeOf(graph, problem.tile);
        found.push_back(std::string(problemKindName(problem.kind)) + " " + std::to_string(place.column) +
                        "," + std::to_string(place.row));
    }
    EXPECT_EQ(found, (std::vector<std::string>{"open-end 1,0", "open-end 2,0", "joins-nothing 5,0",
                                               "joins-nothing 0,2", "turnout-leg-nowhere 1,2",
                                               "turnout-leg-nowhere 1,2", "no-contact 2,2", "open-end 3,2"}))
        << describeGraph(graph);
}

TEST(TrackGraph, APageOfNothingButContactsIsAnS88DisplayNotTrack) {
    DrawnPage track(0, "Strecke");
    track.bufferStop(0, 0, true).contact(1, 0, 1).bufferStop(2, 0, false);
    DrawnPage indicators(1, "S88 Anzeige");
    for (int row = 0; row < 2; ++row)
        for (int column = 0; column < 8; ++column)
            indicators.contact(column, row, 1000 + 8 * row + column);
    const TrackGraph graph = derived({track, indicators});
    EXPECT_TRUE(graph.problems().empty());
    ASSERT_EQ(graph.blocks().size(), 1U);
    EXPECT_FALSE(blockWith(graph, 1000));
}

TEST(TrackGraph, APageWhereNoTrackJoinsIsOneProblemNotOneForEachTile) {
    DrawnPage track(0, "Strecke");
    track.bufferStop(0, 0, true).contact(1, 0, 1).bufferStop(2, 0, false);
    DrawnPage scattered(1, "Vorrat");
    scattered.tile(0, 0, "gerade").tile(2, 0, "signal").tile(4, 4, "linksweiche").tile(6, 0, "pfeil");
    const TrackGraph graph = derived({track, scattered});
    ASSERT_EQ(graph.problems().size(), 1U);
    EXPECT_EQ(graph.problems()[0].kind, ProblemKind::JoinsNothing);
    EXPECT_EQ(placeOf(graph, graph.problems()[0].tile), (TilePlace{1, 0, 0}));
    EXPECT_EQ(
        graph.problems()[0].text,
        "No track on page 'Vorrat' joins another tile (3 tiles stand alone); the page is left out of the "
        "graph.");
}

TEST(TrackGraph, AContactOnTwoStretchesOfOnePageIsOneBlockAndAProblem) {
    DrawnPage page(0, "Bahnhof");
    page.bufferStop(0, 0, true).contact(1, 0, 4).bufferStop(2, 0, false);
    page.bufferStop(0, 2, true).contact(1, 2, 4).bufferStop(2, 2, false);
    const TrackGraph graph = derived({page});
    ASSERT_EQ(graph.blocks().size(), 1U);
    EXPECT_EQ(graph.block(1).tiles.size(), 6U);
    ASSERT_EQ(graph.problems().size(), 1U);
    EXPECT_EQ(graph.problems()[0].kind, ProblemKind::ContactInTwoBlocks);
    EXPECT_EQ(placeOf(graph, graph.problems()[0].tile), (TilePlace{0, 1, 2}));
    EXPECT_EQ(
        graph.problems()[0].text,
        "Contact 4 is drawn here and again at column 1, row 0 of this page, on another stretch of track; "
        "one contact can watch only one block, so both are taken as block 'Block 4'.");
}

TEST(TrackGraph, TheSameContactNumberOnAnotherFeedbackDeviceIsAnotherContact) {
    DrawnPage page(0, "Bahnhof");
    page.bufferStop(0, 0, true).tile(1, 0, "s88kontakt", 0, 4, "", 0x100).bufferStop(2, 0, false);
    page.bufferStop(0, 2, true).tile(1, 2, "s88kontakt", 0, 4, "", 0x200).bufferStop(2, 2, false);
    const TrackGraph graph = derived({page});
    EXPECT_EQ(graph.blocks().size(), 2U);
    EXPECT_TRUE(graph.problems().empty());
    EXPECT_TRUE(blockWith(graph, 4, 0x100));
    EXPECT_FALSE(blockWith(graph, 4, 0));
}

TEST(TrackGraph, RoutesAreCheckedAgainstTheConnections) {
    cs2config::RouteFile routes;
    const auto route = [](std::int64_t id, std::string name, std::int64_t article, std::int64_t position) {
        cs2config::Route r;
        r.id = id;
        r.name = std::move(name);
        cs2config::RouteStep step;
        step.accessory = article;
        step.position = position;
        r.steps.push_back(step);
        return r;
    };
    routes.routes = {route(1, "Nach Gerade", 5, 1), route(2, "Gibt es nicht", 5, 2),
                     route(3, "Nur Signal", 44, 1)};
    DrawnPage page = turnoutFan();
    page.tile(0, 3, "fahrstrasse", 0, 2, "Falsch");
    const std::vector<DrawnPage> pages{page};
    GraphSource source = sourceOf(pages);
    source.routes = &routes;
    const TrackGraph graph = derived(source);
    for (const Connection& connection : graph.connections()) {
        const bool straight = connection.turnouts[0].position == 1;
        EXPECT_EQ(connection.routes, straight ? std::vector<std::int64_t>{1} : std::vector<std::int64_t>{});
    }
    ASSERT_EQ(graph.problems().size(), 1U);
    EXPECT_EQ(graph.problems()[0].kind, ProblemKind::RouteNoConnection);
    EXPECT_EQ(placeOf(graph, graph.problems()[0].tile), (TilePlace{0, 0, 3})); // its button
    EXPECT_EQ(graph.problems()[0].text, "Route 'Gibt es nicht' (2) sets turnout 5 to position 2, which "
                                        "together lead from no block to another as "
                                        "the plan draws them; check the route's turnouts against the plan.");
}

TEST(TrackGraph, TheSameInputGivesTheSameGraphWhateverTheOrderOfThePagesInTheIndex) {
    DrawnPage strecke(0, "Strecke");
    strecke.bufferStop(0, 0, true).contact(1, 0, 5).straight(2, 3, 0).arrow(4, 0, 0, 1, "Bahnhof");
    DrawnPage bahnhof(1, "Bahnhof");
    bahnhof.arrow(0, 0, 2, 0, "Strecke").straight(1, 1, 0).contact(2, 0, 6).bufferStop(3, 0, false);
    EXPECT_EQ(toJson(derived({strecke, bahnhof})), toJson(derived({bahnhof, strecke})));
    EXPECT_EQ(toJson(derived({strecke, bahnhof})), toJson(derived({strecke, bahnhof})));
}
