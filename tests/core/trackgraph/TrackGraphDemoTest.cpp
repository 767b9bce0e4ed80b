// The graph of the demo layout (resources/demo-layout) against the hand-written table the simulator moved
// its trains on before it ran them on this graph (core/sim/DemoLayoutTrack.cpp, retired; written out below):
// the same sections, contacts and ways, section by section, and the turnouts and positions that choose
// between them.
#include "TrackGraphTestSupport.h"
#include "trackgraph/GraphReport.h"

#include <QByteArray>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>
#include <map>
#include <set>

using namespace stellwerk;
using namespace stellwerk::trackgraph;
using namespace stellwerk::trackgraph::test;

namespace {

const TrackGraph& demo() {
    static const FolderGraph folder(STELLWERK_DEMO_LAYOUT_DIR);
    return folder.graph;
}

int idOf(const std::string& name) {
    for (const Block& block : demo().blocks())
        if (block.name == name)
            return block.id;
    ADD_FAILURE() << "no block " << name;
    return 0;
}

// The ways from a block end as "<block name> <turnout>:<position>" (no turnout: the name alone).
std::set<std::string> waysByName(const BlockEnd& end) {
    std::set<std::string> ways;
    for (const int id : demo().connectionsFrom(end)) {
        const Connection& connection = demo().connection(id);
        std::string way = demo().block(connection.to.block).name;
        for (const TurnoutOnWay& turnout : connection.turnouts)
            way += " W" + std::to_string(*turnout.article) + ":" +
                   std::string(positionName(turnout.kind, turnout.position));
        ways.insert(way);
    }
    return ways;
}

// The retired table: each section with its contact and the ways "ahead" and "behind" it, a facing turnout
// giving both branches with the position that leads there (the table named no turnout passed trailing).
struct RetiredSection {
    std::string name;
    std::int64_t contact;
    std::set<std::string> ahead;
    std::set<std::string> behind;
};

const std::vector<RetiredSection>& retiredTable() {
    static const std::vector<RetiredSection> table = {
        {"Einfahrt West", 7, {"Gleis 1 W1:straight", "Gleis 2 W1:diverging"}, {"Block 4"}},
        {"Gleis 1", 1, {"Ausfahrt Ost"}, {"Einfahrt West"}},
        {"Gleis 2", 2, {"Ausfahrt Ost"}, {"Einfahrt West"}},
        {"Ausfahrt Ost",
         8,
         {"Block 1 W3:straight", "Abstellgleis W3:diverging"},
         {"Gleis 1 W2:straight", "Gleis 2 W2:diverging"}},
        {"Block 1", 3, {"Block 2"}, {"Ausfahrt Ost"}},
        {"Block 2", 4, {"Block 3"}, {"Block 1"}},
        {"Block 3", 5, {"Block 4"}, {"Block 2"}},
        {"Block 4", 6, {"Einfahrt West"}, {"Block 3"}},
        {"Abstellgleis", 9, {}, {"Ausfahrt Ost"}},
    };
    return table;
}

std::set<std::string> facingOnly(const BlockEnd& end) {
    std::set<std::string> ways;
    for (const int id : demo().connectionsFrom(end)) {
        const Connection& connection = demo().connection(id);
        std::string way = demo().block(connection.to.block).name;
        for (const TurnoutOnWay& turnout : connection.turnouts)
            if (turnout.facing)
                way += " W" + std::to_string(*turnout.article) + ":" +
                       std::string(positionName(turnout.kind, turnout.position));
        ways.insert(way);
    }
    return ways;
}

} // namespace

TEST(TrackGraphDemo, TheBlocksAreTheRetiredTablesSectionsWithTheirContacts) {
    ASSERT_EQ(demo().blocks().size(), retiredTable().size());
    for (const RetiredSection& section : retiredTable()) {
        const Block* block = blockWith(demo(), section.contact);
        ASSERT_NE(block, nullptr) << section.name;
        EXPECT_EQ(block->name, section.name);
        EXPECT_EQ(contactNumbers(*block), std::vector<std::int64_t>{section.contact});
    }
}

TEST(TrackGraphDemo, EachBlockEndLeadsWhereTheRetiredTableSaid) {
    for (const RetiredSection& section : retiredTable()) {
        const int block = idOf(section.name);
        // Which end was "ahead" was the table's own choice: the two ends must be its two exits.
        const std::set<std::set<std::string>> graphEnds{facingOnly({block, End::A}),
                                                        facingOnly({block, End::B})};
        const std::set<std::set<std::string>> tableEnds{section.ahead, section.behind};
        EXPECT_EQ(graphEnds, tableEnds) << section.name;
    }
}

TEST(TrackGraphDemo, BlocksOneByOne) {
    struct Expected {
        std::string name;
        std::int64_t contact;
        std::set<std::string> a;
        std::set<std::string> b;
    };
    // Read off the pages: end a is the end whose tile comes first (page, row, column).
    const Expected expected[] = {
        {"Gleis 2", 2, {"Einfahrt West W1:diverging"}, {"Ausfahrt Ost W2:diverging"}},
        {"Abstellgleis", 9, {"Ausfahrt Ost W3:diverging"}, {}}, // b: the Bw's tracks, no contact on them
        {"Einfahrt West", 7, {"Gleis 1 W1:straight", "Gleis 2 W1:diverging"}, {"Block 4"}},
        {"Gleis 1", 1, {"Einfahrt West W1:straight"}, {"Ausfahrt Ost W2:straight"}},
        {"Ausfahrt Ost",
         8,
         {"Gleis 1 W2:straight", "Gleis 2 W2:diverging"},
         {"Block 1 W3:straight", "Abstellgleis W3:diverging"}},
        {"Block 1", 3, {"Ausfahrt Ost W3:straight"}, {"Block 2"}},
        {"Block 2", 4, {"Block 1"}, {"Block 3"}},
        {"Block 3", 5, {"Block 2"}, {"Block 4"}},
        {"Block 4", 6, {"Einfahrt West"}, {"Block 3"}},
    };
    ASSERT_EQ(demo().blocks().size(), std::size(expected));
    for (std::size_t i = 0; i < std::size(expected); ++i) {
        const Block& block = demo().blocks()[i];
        EXPECT_EQ(block.name, expected[i].name);
        EXPECT_EQ(contactNumbers(block), std::vector<std::int64_t>{expected[i].contact});
        EXPECT_EQ(waysByName({block.id, End::A}), expected[i].a) << block.name;
        EXPECT_EQ(waysByName({block.id, End::B}), expected[i].b) << block.name;
    }
}

TEST(TrackGraphDemo, EndsSignalsAndLengthsOfEinfahrtWest) {
    // Bahnhof row 5: the arrow to the Strecke (0), contact 7 (1), signal A (2), track (3), W1's points
    // (4); the Strecke's arrow (0) and two tiles (1, 2) up to halfway to contact 6 (Block 4).
    const Block& block = demo().block(idOf("Einfahrt West"));
    EXPECT_EQ(placeOf(demo(), block.end(End::A).tile), (TilePlace{0, 3, 5}));
    EXPECT_EQ(block.end(End::A).port, Port::East);
    EXPECT_EQ(block.end(End::A).beyond, EndKind::Junction);
    EXPECT_EQ(placeOf(demo(), block.end(End::B).tile), (TilePlace{1, 1, 5}));
    EXPECT_EQ(block.end(End::B).beyond, EndKind::Block);
    EXPECT_EQ(block.lengthTiles(), 6);
    EXPECT_EQ(block.lengthMm, 4 * 180 + 2 * 90); // two half tiles of arrows
    ASSERT_EQ(block.signalsAlong.size(), 1U);
    EXPECT_EQ(block.signalsAlong[0].name, "A");
    EXPECT_EQ(block.signalsAlong[0].article, 6);
    EXPECT_EQ(block.signalsAlong[0].towards, End::A); // it faces the trains running into the station
    EXPECT_EQ(block.signalsAlong[0].atMm, 180 + 90);
    ASSERT_EQ(block.contacts.size(), 1U);
    EXPECT_EQ(block.contacts[0].fromMm, 2 * 180);
    EXPECT_EQ(block.contacts[0].toMm, 3 * 180);
    EXPECT_EQ(placeOf(demo(), block.contacts[0].tile), (TilePlace{0, 1, 5}));
}

TEST(TrackGraphDemo, SignalsBetweenBlocksEndTheBlockTheyHoldTrainsIn) {
    // Strecke row 2: Block 1 (contact 3 at column 3), signal F (6) facing east, Block 2 (contact 4 at 10).
    const Block& first = demo().block(idOf("Block 1"));
    ASSERT_EQ(first.signalsAlong.size(), 1U);
    EXPECT_EQ(first.signalsAlong[0].name, "F");
    EXPECT_EQ(first.signalsAlong[0].towards, End::B);
    EXPECT_EQ(placeOf(demo(), first.end(End::B).tile), (TilePlace{1, 6, 2}));
    EXPECT_EQ(placeOf(demo(), demo().block(idOf("Block 2")).end(End::A).tile), (TilePlace{1, 7, 2}));
    // Block 3 and Block 4 have no signal between them: cut halfway (columns 6 .. 11 between them).
    EXPECT_EQ(placeOf(demo(), demo().block(idOf("Block 3")).end(End::B).tile), (TilePlace{1, 9, 5}));
    EXPECT_EQ(placeOf(demo(), demo().block(idOf("Block 4")).end(End::B).tile), (TilePlace{1, 8, 5}));
}

TEST(TrackGraphDemo, ConnectionsNameTheirTurnoutsFacingOrTrailing) {
    const int entry = idOf("Einfahrt West");
    const int track1 = idOf("Gleis 1");
    for (const Connection& connection : demo().connections()) {
        if (connection.from.block == entry && connection.to.block == track1) {
            ASSERT_EQ(connection.turnouts.size(), 1U);
            EXPECT_EQ(connection.turnouts[0].article, 1);
            EXPECT_EQ(connection.turnouts[0].position, 1);
            EXPECT_TRUE(connection.turnouts[0].facing);
            EXPECT_EQ(placeOf(demo(), connection.turnouts[0].tile), (TilePlace{0, 4, 5}));
            EXPECT_EQ(connection.path.size(), 1U);                      // W1 itself
            EXPECT_EQ(connection.routes, std::vector<std::int64_t>{1}); // "Einfahrt Gleis 1"
        }
        if (connection.from.block == track1 && connection.to.block == entry) {
            ASSERT_EQ(connection.turnouts.size(), 1U);
            EXPECT_FALSE(connection.turnouts[0].facing);
        }
    }
}

TEST(TrackGraphDemo, TheBwsTracksWithoutContactAreTheOnlyProblems) {
    ASSERT_EQ(demo().problems().size(), 3U);
    for (const Problem& problem : demo().problems()) {
        EXPECT_EQ(problem.kind, ProblemKind::NoContact);
        EXPECT_EQ(placeOf(demo(), problem.tile).page, 2); // Bw
    }
    EXPECT_EQ(
        demo().problems()[0].text,
        "These 8 tiles of track between turnout 4 and a buffer stop have no contact, so a train there cannot "
        "be seen; add a contact where trains may stop.");
}

TEST(TrackGraphDemo, RoutesAreNamedOnTheConnectionsTheySet) {
    std::map<std::int64_t, std::set<std::string>> routes;
    for (const Connection& connection : demo().connections())
        for (const std::int64_t route : connection.routes)
            routes[route].insert(demo().block(connection.from.block).name + " > " +
                                 demo().block(connection.to.block).name);
    EXPECT_EQ(routes[1], (std::set<std::string>{"Einfahrt West > Gleis 1", "Gleis 1 > Einfahrt West"}));
    // "Einfahrt Gleis 2" also sets W2 to Gleis 2 (flank protection): it sets those connections too.
    EXPECT_EQ(routes[2], (std::set<std::string>{"Einfahrt West > Gleis 2", "Gleis 2 > Einfahrt West",
                                                "Gleis 2 > Ausfahrt Ost", "Ausfahrt Ost > Gleis 2"}));
    EXPECT_EQ(routes[3], (std::set<std::string>{"Gleis 1 > Ausfahrt Ost", "Ausfahrt Ost > Gleis 1"}));
    EXPECT_EQ(routes[4], (std::set<std::string>{"Gleis 2 > Ausfahrt Ost", "Ausfahrt Ost > Gleis 2"}));
    EXPECT_EQ(routes.count(5), 0U); // "Alles auf Halt" sets signals only
}

TEST(TrackGraphDemo, FollowingTheTrackWithTheTurnoutsAsTheyStand) {
    const int entry = idOf("Einfahrt West");
    std::map<std::int64_t, int> positions{{1, 1}, {2, 1}, {3, 1}, {4, 1}};
    const PositionOf positionOf = [&positions](std::int64_t article) -> std::optional<int> {
        const auto found = positions.find(article);
        return found == positions.end() ? std::nullopt : std::optional(found->second);
    };
    Lead lead = demo().follow({entry, End::A}, positionOf);
    EXPECT_EQ(lead.kind, LeadKind::Block);
    EXPECT_EQ(lead.reached, (BlockEnd{idOf("Gleis 1"), End::A}));
    ASSERT_EQ(lead.path.size(), 1U);
    EXPECT_EQ(placeOf(demo(), lead.path[0].tile), (TilePlace{0, 4, 5}));
    positions[1] = 0;
    EXPECT_EQ(demo().follow({entry, End::A}, positionOf).reached, (BlockEnd{idOf("Gleis 2"), End::A}));
    // Out of Gleis 1 towards W1 set for Gleis 2: trailing through it.
    lead = demo().follow({idOf("Gleis 1"), End::A}, positionOf);
    EXPECT_EQ(lead.kind, LeadKind::SetAgainst);
    EXPECT_EQ(lead.article, 1);
    // Beyond the Abstellgleis: the Bw, W4 straight into Lokschuppen 2's buffer stop.
    lead = demo().follow({idOf("Abstellgleis"), End::B}, positionOf);
    EXPECT_EQ(lead.kind, LeadKind::BufferStop);
    EXPECT_EQ(lead.path.size(), 8U); // W4 and the seven tiles up to Lokschuppen 2's buffer stop
    positions.erase(4);
    lead = demo().follow({idOf("Abstellgleis"), End::B}, positionOf);
    EXPECT_EQ(lead.kind, LeadKind::NotSet);
    EXPECT_EQ(placeOf(demo(), *lead.turnout), (TilePlace{2, 3, 2}));
    // Straight on between blocks: nothing between them.
    lead = demo().follow({idOf("Block 2"), End::B}, positionOf);
    EXPECT_EQ(lead.reached, (BlockEnd{idOf("Block 3"), End::A}));
    EXPECT_TRUE(lead.path.empty());
}

TEST(TrackGraphDemo, FollowingOnFromATileBetweenBlocks) {
    // From W4's tile in the Bw (page 2, column 3, row 2), as a train there would go on: into a buffer stop
    // after seven tiles, whichever way W4 lies.
    const std::map<std::int64_t, int> positions{{4, 1}};
    const PositionOf positionOf = [&positions](std::int64_t article) -> std::optional<int> {
        const auto found = positions.find(article);
        return found == positions.end() ? std::nullopt : std::optional(found->second);
    };
    const Lead fromBlock = demo().follow({idOf("Abstellgleis"), End::B}, positionOf);
    ASSERT_EQ(fromBlock.kind, LeadKind::BufferStop);
    const TrackStep& w4 = fromBlock.path.front();
    const Lead fromW4 = demo().followFrom(w4.tile, w4.exit, positionOf);
    EXPECT_EQ(fromW4.kind, LeadKind::BufferStop);
    EXPECT_EQ(fromW4.path, std::vector<TrackStep>(fromBlock.path.begin() + 1, fromBlock.path.end()));
    // Leaving W4 the way the train came: straight back into the Abstellgleis through its end b.
    const Lead back = demo().followFrom(w4.tile, w4.entry, positionOf);
    EXPECT_EQ(back.kind, LeadKind::Block);
    EXPECT_EQ(back.reached, (BlockEnd{idOf("Abstellgleis"), End::B}));
}

TEST(TrackGraphDemo, TilesKnowTheirBlocksAndProblems) {
    const TrackGraph& graph = demo();
    const std::optional<TileId> contact = graph.tileAt({0, 7, 5});
    ASSERT_TRUE(contact);
    EXPECT_EQ(graph.blocksAt(*contact), std::vector<int>{idOf("Gleis 1")});
    const std::optional<TileId> turnout = graph.tileAt({0, 4, 5});
    ASSERT_TRUE(turnout);
    EXPECT_TRUE(graph.blocksAt(*turnout).empty());
    EXPECT_FALSE(graph.tileAt({0, 0, 0}));
    const Block& strecke = graph.block(idOf("Block 4"));
    for (const TileId tile : strecke.tiles)
        EXPECT_EQ(graph.blocksAt(tile), std::vector<int>{strecke.id});
    EXPECT_EQ(graph.problemsAt(graph.problems()[0].tile).size(), 1U);
    EXPECT_EQ(graph.blockEndAt(strecke.end(End::B).tile, strecke.end(End::B).port),
              (BlockEnd{strecke.id, End::B}));
}

TEST(TrackGraphDemo, DerivingTwiceGivesTheSameGraph) {
    const FolderGraph again(STELLWERK_DEMO_LAYOUT_DIR);
    EXPECT_EQ(toJson(again.graph), toJson(demo()));
}

TEST(TrackGraphDemo, TheJsonHasEveryFieldTheGuideNames) {
    const QJsonObject json = QJsonDocument::fromJson(QByteArray::fromStdString(toJson(demo()))).object();
    const QJsonArray blocks = json["blocks"].toArray();
    ASSERT_EQ(blocks.size(), 9);
    const QJsonObject entry = blocks[2].toObject();
    EXPECT_EQ(entry["id"].toInt(), 3);
    EXPECT_EQ(entry["name"].toString(), "Einfahrt West");
    EXPECT_EQ(entry["contacts"].toArray(), QJsonArray{7});
    EXPECT_EQ(entry["length"].toInt(), 6);
    EXPECT_EQ(entry["lengthMm"].toInt(), 900);
    EXPECT_EQ(entry["tiles"].toArray()[0].toObject(), (QJsonObject{{"page", 0}, {"x", 0}, {"y", 5}}));
    EXPECT_EQ(entry["ends"].toObject()["a"].toObject()["beyond"].toString(), "junction");
    EXPECT_EQ(entry["signals"].toArray()[0].toObject()["towards"].toString(), "a");
    const QJsonArray connections = json["connections"].toArray();
    QJsonObject toTrack1;
    for (const QJsonValue connection : connections)
        if (connection["from"].toObject() == QJsonObject{{"block", 3}, {"end", "a"}} &&
            connection["to"].toObject()["block"].toInt() == idOf("Gleis 1"))
            toTrack1 = connection.toObject();
    const QJsonObject turnout = toTrack1["turnouts"].toArray()[0].toObject();
    EXPECT_EQ(turnout["article"].toInt(), 1);
    EXPECT_EQ(turnout["position"].toString(), "straight");
    EXPECT_EQ(toTrack1["crossings"].toArray().size(), 0);
    EXPECT_EQ(toTrack1["routes"].toArray(), QJsonArray{1});
    const QJsonObject problem = json["problems"].toArray()[0].toObject();
    EXPECT_EQ(problem["page"].toInt(), 2);
    EXPECT_EQ(problem["x"].toInt(), 3);
    EXPECT_EQ(problem["y"].toInt(), 1);
    EXPECT_EQ(problem["kind"].toString(), "no-contact");
    EXPECT_FALSE(problem["text"].toString().isEmpty());
}
