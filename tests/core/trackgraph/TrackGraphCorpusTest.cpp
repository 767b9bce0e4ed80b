// The real pages of ../shared/corpus (read in place; a missing file fails the test): karben.cs2 and
// TrainControl's page "5 - Test" with the blocks, connections and problems read off the pages by hand, and
// every track plan of the corpus derived without a broken invariant.
#include "TrackGraphTestSupport.h"
#include "cs2config/ConfigFile.h"
#include "trackgraph/GraphReport.h"

#include <filesystem>
#include <map>
#include <set>

using namespace stellwerk;
using namespace stellwerk::trackgraph;
using namespace stellwerk::trackgraph::test;
namespace fs = std::filesystem;

namespace {

fs::path corpus(const std::string& relative) {
    const fs::path path = fs::path(STELLWERK_SHARED_DIR) / "corpus" / relative;
    EXPECT_TRUE(fs::exists(path)) << "corpus file missing: " << path;
    return path;
}

// "kind column,row" of every problem, in the graph's order.
std::vector<std::string> problemPlaces(const TrackGraph& graph) {
    std::vector<std::string> places;
    for (const Problem& problem : graph.problems()) {
        const TilePlace place = placeOf(graph, problem.tile);
        places.push_back(std::string(problemKindName(problem.kind)) + " " + std::to_string(place.column) +
                         "," + std::to_string(place.row));
    }
    return places;
}

std::string textAt(const TrackGraph& graph, ProblemKind kind, int column, int row) {
    for (const Problem& problem : graph.problems())
        if (problem.kind == kind && placeOf(graph, problem.tile).column == column &&
            placeOf(graph, problem.tile).row == row)
            return problem.text;
    return {};
}

} // namespace

// karben.cs2: three station tracks (rows 1-3) with a contact each (device 0x100), joined by two
// crossovers on turnout 1 (23 and 22; 13 too: the page gives three turnouts .artikel=2) and one on turnouts
// 2 and 3; every track runs off the page at both ends, so no way joins two blocks without reversing.
TEST(TrackGraphCorpus, KarbenHasThreeStationTracksAndNoConnection) {
    const FolderGraph folder(corpus("GBert__railroad/can2udp/files/maerklin"));
    const TrackGraph& graph = folder.graph;
    ASSERT_EQ(graph.blocks().size(), 3U) << describeGraph(graph);
    const std::pair<std::string, std::int64_t> expected[] = {{"603", 101}, {"602", 102}, {"601", 103}};
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(graph.blocks()[i].name, expected[i].first);
        ASSERT_EQ(graph.blocks()[i].contacts.size(), 1U);
        EXPECT_EQ(graph.blocks()[i].contacts[0].contact, (ContactKey{0x100, expected[i].second}));
    }
    // 603 between turnout 23 (column 5) and 13 (column 9); signal D faces trains running west.
    const Block& top = graph.block(1);
    EXPECT_EQ(placeOf(graph, top.end(End::A).tile), (TilePlace{0, 6, 1}));
    EXPECT_EQ(placeOf(graph, top.end(End::B).tile), (TilePlace{0, 8, 1}));
    ASSERT_EQ(top.signalsAlong.size(), 1U);
    EXPECT_EQ(top.signalsAlong[0].name, "D");
    EXPECT_EQ(top.signalsAlong[0].towards, End::A);
    // 602 has signals both ways (E east, C west); 601 runs from column 4 to 10 with B.
    EXPECT_EQ(graph.block(2).signalsAlong.size(), 2U);
    EXPECT_EQ(graph.block(3).lengthTiles(), 7);
    EXPECT_TRUE(graph.connections().empty());
    EXPECT_EQ(problemPlaces(graph),
              (std::vector<std::string>{"no-contact 2,1", "no-contact 10,1", "open-end 1,2", "no-contact 3,2",
                                        "no-contact 10,2", "open-end 13,2", "open-end 1,3", "no-contact 1,3",
                                        "no-contact 12,3", "open-end 13,3"}));
    EXPECT_EQ(
        textAt(graph, ProblemKind::NoContact, 3, 2),
        "These 2 tiles of track between turnout 2 and turnout 1 have no contact, so a train there cannot be "
        "seen; add a contact where trains may stop.");
    EXPECT_EQ(
        textAt(graph, ProblemKind::OpenEnd, 13, 2),
        "The track ends at the east side without a buffer stop; add the missing track or a buffer stop.");
}

TEST(TrackGraphCorpus, KarbensWaysRunOffThePage) {
    const FolderGraph folder(corpus("GBert__railroad/can2udp/files/maerklin"));
    const TrackGraph& graph = folder.graph;
    // From 602 west: turnout 22 straight, round into 24's diverging leg and off the page at column 1.
    const PositionOf straight = [](std::int64_t) { return std::optional(1); };
    const PositionOf diverging = [](std::int64_t) { return std::optional(0); };
    EXPECT_EQ(graph.follow({2, End::A}, straight).kind, LeadKind::SetAgainst); // 24 is straight
    const Lead off = graph.follow({2, End::A}, [](std::int64_t article) {
        return std::optional(article == 2 ? 0 : 1); // 24 diverging, 22 straight
    });
    EXPECT_EQ(off.kind, LeadKind::OpenEnd);
    EXPECT_EQ(placeOf(graph, off.path.back().tile), (TilePlace{0, 1, 3}));
    // Diverging at 22 leads up over 23 (the same article) and off the page west of row 1.
    EXPECT_EQ(graph.follow({2, End::A}, diverging).kind, LeadKind::OpenEnd);
}

// "5 - Test" of TrainControl's sample: nearly every tile type, most of them standing alone. Two contacts lie
// on track: 1031 between the three-way turnout 23 and an open end, 1009 between turnouts 58 and 36.
TEST(TrackGraphCorpus, TrainControlsTestPageHasTwoBlocksAndItsLooseTilesReported) {
    const FolderGraph folder(corpus("bob123456678__TrainControl/cs2_sample_layout"));
    const TrackGraph& graph = folder.graph;
    ASSERT_EQ(graph.blocks().size(), 2U) << describeGraph(graph);
    EXPECT_EQ(graph.block(1).name, "Block 1031");
    EXPECT_EQ(placeOf(graph, graph.block(1).end(End::A).tile), (TilePlace{5, 4, 6}));
    EXPECT_EQ(graph.block(1).end(End::A).beyond, EndKind::OpenEnd);
    EXPECT_EQ(graph.block(1).end(End::B).beyond, EndKind::Junction);
    EXPECT_EQ(graph.block(2).name, "Block 1009");
    EXPECT_EQ(graph.block(2).lengthTiles(), 1);
    EXPECT_TRUE(graph.connections().empty());
    std::map<ProblemKind, std::size_t> kinds;
    for (const Problem& problem : graph.problems())
        ++kinds[problem.kind];
    EXPECT_EQ(kinds, (std::map<ProblemKind, std::size_t>{{ProblemKind::OpenEnd, 20},
                                                         {ProblemKind::JoinsNothing, 43},
                                                         {ProblemKind::TurnoutLegNowhere, 14},
                                                         {ProblemKind::NoContact, 11}}));
    // The crossing at column 16, row 10 has nothing north and south of it; the underpass beside it neither.
    EXPECT_EQ(
        textAt(graph, ProblemKind::OpenEnd, 16, 10),
        "The track ends at the north side without a buffer stop; add the missing track or a buffer stop.");
    EXPECT_EQ(
        textAt(graph, ProblemKind::NoContact, 13, 10),
        "These 4 tiles of track between the crossing at column 16, row 10 and turnout 90 have no contact, so "
        "a train there cannot be seen; add a contact where trains may stop.");
    EXPECT_EQ(textAt(graph, ProblemKind::JoinsNothing, 25, 12),
              "This hosentraeger tile joins no other track; move it onto the track or remove it.");
    EXPECT_EQ(
        textAt(graph, ProblemKind::OpenEnd, 8, 16),
        "The track at the east side does not meet the track of the tile beside it (column 9, row 16); turn "
        "one of them or add a buffer stop.");
    EXPECT_EQ(textAt(graph, ProblemKind::TurnoutLegNowhere, 3, 6),
              "Turnout 23 has no track at its north side, so the way through it there leads nowhere; add the "
              "track or a buffer stop.");
}

// Every page of every track plan in the corpus: the index files with the pages beside them, and each page
// file on its own (gbs-0.cs2 is a page as the CAN stream names it).
TEST(TrackGraphCorpus, EveryRealPageDerivesKeepingTheInvariants) {
    const fs::path root = corpus("");
    std::set<std::string> read;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(root)) {
        if (!entry.is_regular_file() || entry.path().extension() != ".cs2")
            continue;
        const cs2config::ConfigFile file = cs2config::ConfigFile::load(entry.path());
        const std::string name = fs::relative(entry.path(), root).generic_string();
        GraphSource source;
        cs2config::TrackLayout layout;
        if (file.model<cs2config::TrackPlan>()) {
            layout = cs2config::TrackLayout::load(entry.path());
            source = GraphSource::of(layout);
        } else if (const cs2config::TrackPage* page = file.model<cs2config::TrackPage>()) {
            source.pages.push_back({0, entry.path().stem().string(), &page->elements});
        } else {
            continue;
        }
        read.insert(name);
        const TrackGraph graph = TrackGraph::derive(source);
        EXPECT_EQ(brokenInvariants(graph), std::vector<std::string>{}) << name;
        EXPECT_EQ(toJson(TrackGraph::derive(source)), toJson(graph)) << name;
    }
    for (const char* expected :
         {"GBert__railroad/can2udp/files/maerklin/config/gleisbild.cs2",
          "GBert__railroad/can2udp/files/maerklin/config/gleisbilder/karben.cs2",
          "GBert__railroad/can2udp/src/gbs-0.cs2", "MrFlexi__TrainControll/gleisbild.cs2",
          "bob123456678__TrainControl/cs2_sample_layout/config/gleisbild.cs2",
          "bob123456678__TrainControl/cs2_sample_layout/config/gleisbilder/5 - Test.cs2"})
        EXPECT_TRUE(read.count(expected)) << "not read as a track plan: " << expected;
}

TEST(TrackGraphCorpus, AnS88DisplayPageIsNoTrack) {
    const cs2config::ConfigFile file =
        cs2config::ConfigFile::load(corpus("GBert__railroad/can2udp/src/gbs-0.cs2"));
    const cs2config::TrackPage* page = file.model<cs2config::TrackPage>();
    ASSERT_NE(page, nullptr);
    GraphSource source;
    source.pages.push_back({0, "gbs-0", &page->elements});
    const TrackGraph graph = derived(source);
    EXPECT_EQ(graph.tiles().size(), 144U);
    EXPECT_TRUE(graph.blocks().empty());
    EXPECT_TRUE(graph.problems().empty());
}
