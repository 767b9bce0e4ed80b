// Track over several pages: arrows (`pfeil`) carrying it on, and an overview page drawing the same
// contacts as the detail pages: one block each, and a problem where the drawings disagree.
#include "TrackGraphTestSupport.h"

using namespace stellwerk;
using namespace stellwerk::trackgraph;
using namespace stellwerk::trackgraph::test;

namespace {

// Strecke (page 0): a buffer stop, contact 5, an arrow east to the Bahnhof. Bahnhof (page 1): the arrow back,
// contact 6, a buffer stop.
DrawnPage strecke() {
    DrawnPage page(0, "Strecke");
    page.bufferStop(0, 0, true).straight(1, 1, 0).contact(2, 0, 5, "Ost").straight(3, 3, 0);
    page.arrow(4, 0, 0, 1, "Bahnhof");
    return page;
}

DrawnPage bahnhof() {
    DrawnPage page(1, "Bahnhof");
    page.arrow(0, 0, 2, 0, "Strecke").straight(1, 1, 0).contact(2, 0, 6, "Gleis").straight(3, 3, 0);
    page.bufferStop(4, 0, false);
    return page;
}

// The overview (page 2): the line at a glance, with `contacts` from west to east.
DrawnPage overview(const std::vector<std::int64_t>& contacts) {
    DrawnPage page(2, "Übersicht");
    page.bufferStop(0, 0, true);
    int column = 1;
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        if (i > 0)
            page.straight(column, column + 1, 0), column += 2;
        page.contact(column++, 0, contacts[i]);
    }
    page.bufferStop(column, 0, false);
    return page;
}

std::vector<std::int64_t> pagesOf(const TrackGraph& graph, const Block& block) {
    std::vector<std::int64_t> pages;
    for (const TileId tile : block.tiles)
        if (pages.empty() || pages.back() != graph.tile(tile).place.page)
            pages.push_back(graph.tile(tile).place.page);
    return pages;
}

} // namespace

TEST(TrackGraphPages, AnArrowCarriesTheTrackOnToThePageItNames) {
    const TrackGraph graph = derived({strecke(), bahnhof()});
    ASSERT_EQ(graph.blocks().size(), 2U);
    EXPECT_EQ(graph.block(1).name, "Ost");
    EXPECT_EQ(graph.block(2).name, "Gleis");
    // Halfway between the contacts: two tiles each side, the arrows' halves counted.
    EXPECT_EQ(pagesOf(graph, graph.block(1)), std::vector<std::int64_t>{0});
    EXPECT_EQ(placeOf(graph, graph.block(2).end(End::A).tile), (TilePlace{1, 0, 0}));
    EXPECT_EQ(graph.block(2).end(End::A).port, Port::Link);
    EXPECT_EQ(waysFrom(graph, {1, End::B}), std::vector<std::string>{"2a"});
    EXPECT_TRUE(graph.problems().empty());
}

TEST(TrackGraphPages, AnArrowMayNameItsPageByName) {
    DrawnPage first(0, "Strecke");
    first.bufferStop(0, 0, true).contact(1, 0, 5).arrow(2, 0, 0, -1, "Bahnhof");
    DrawnPage second(1, "Bahnhof");
    second.arrow(0, 0, 2, -1, "Strecke").contact(1, 0, 6).bufferStop(2, 0, false);
    const TrackGraph graph = derived({first, second});
    EXPECT_EQ(waysFrom(graph, {1, End::B}), std::vector<std::string>{"2a"});
    EXPECT_TRUE(graph.problems().empty());
}

TEST(TrackGraphPages, ArrowsPairWithTheNearestArrowBack) {
    // Two tracks leave the Strecke for the Bahnhof, which draws them a row lower.
    DrawnPage first(0, "Strecke");
    first.bufferStop(0, 1, true).contact(1, 1, 1).arrow(2, 1, 0, 1);
    first.bufferStop(0, 4, true).contact(1, 4, 2).arrow(2, 4, 0, 1);
    DrawnPage second(1, "Bahnhof");
    second.arrow(0, 2, 2, 0).contact(1, 2, 11).bufferStop(2, 2, false);
    second.arrow(0, 5, 2, 0).contact(1, 5, 12).bufferStop(2, 5, false);
    const TrackGraph graph = derived({first, second});
    const auto next = [&graph](std::int64_t contact) {
        const int block = *graph.blockWithContact({0, contact});
        const Connection& way = graph.connection(graph.connectionsFrom({block, End::B}).at(0));
        return contactNumbers(graph.block(way.to.block))[0];
    };
    EXPECT_EQ(next(1), 11);
    EXPECT_EQ(next(2), 12);
}

TEST(TrackGraphPages, AnArrowWithoutAPartnerOrPageIsReported) {
    DrawnPage first(0, "Strecke");
    first.bufferStop(0, 0, true).contact(1, 0, 1).arrow(2, 0, 0, 1, "Bahnhof"); // its partner is on row 2
    first.bufferStop(0, 2, true).contact(1, 2, 2).arrow(2, 2, 0, 1, "Bahnhof");
    first.bufferStop(0, 4, true).contact(1, 4, 3).arrow(2, 4, 0, 9);       // no page 9
    first.bufferStop(0, 6, true).contact(1, 6, 4).arrow(2, 6, 0, 2, "Bw"); // its file is missing
    first.arrow(8, 8, 0, 1, "Bahnhof");                                    // a button, not on track
    DrawnPage second(1, "Bahnhof");
    second.arrow(0, 2, 2, 0).contact(1, 2, 12).bufferStop(2, 2, false);
    const std::vector<DrawnPage> pages{first, second};
    GraphSource source = sourceOf(pages);
    source.pages.push_back({2, "Bw", nullptr});
    const TrackGraph graph = derived(source);
    std::vector<std::string> problems;
    for (const Problem& problem : graph.problems())
        problems.push_back(std::to_string(placeOf(graph, problem.tile).row) + " " + problem.text);
    EXPECT_EQ(problems,
              (std::vector<std::string>{
                  "0 The arrow to page 'Bahnhof' has no arrow back to page 'Strecke' there, so the track "
                  "ends here; add one where the track goes on.",
                  "4 The arrow names page 9, which the track plan does not have; the track ends here.",
                  "6 The arrow leads to page 'Bw', whose file is missing; the track ends here."}));
    EXPECT_EQ(graph.block(*graph.blockWithContact({0, 3})).end(End::B).beyond, EndKind::OpenEnd);
    EXPECT_EQ(graph.pages().size(), 3U);
    EXPECT_FALSE(graph.pages()[2].loaded);
}

TEST(TrackGraphPages, AnOverviewDrawingTheSameContactsAddsNoBlock) {
    const TrackGraph graph = derived({strecke(), bahnhof(), overview({5, 6})});
    ASSERT_EQ(graph.blocks().size(), 2U);
    EXPECT_EQ(contactNumbers(graph.block(1)), std::vector<std::int64_t>{5});
    EXPECT_EQ(contactNumbers(graph.block(2)), std::vector<std::int64_t>{6});
    // Each block is drawn twice: on its detail page and on the overview.
    EXPECT_EQ(pagesOf(graph, graph.block(1)), (std::vector<std::int64_t>{0, 2}));
    EXPECT_EQ(pagesOf(graph, graph.block(2)), (std::vector<std::int64_t>{1, 2}));
    // Its path and ends are those of its first drawing.
    EXPECT_EQ(placeOf(graph, graph.block(1).end(End::A).tile), (TilePlace{0, 0, 0}));
    EXPECT_EQ(graph.blocksAt(*graph.tileAt({2, 1, 0})), std::vector<int>{1});
    // Both drawings lead from 5 to 6: one connection each way.
    EXPECT_EQ(graph.connections().size(), 2U);
    EXPECT_EQ(waysFrom(graph, {1, End::B}), std::vector<std::string>{"2a"});
    EXPECT_TRUE(graph.problems().empty());
}

TEST(TrackGraphPages, AnOverviewDrawnTheOtherWayRoundStillAgrees) {
    const TrackGraph graph = derived({strecke(), bahnhof(), overview({6, 5})});
    ASSERT_EQ(graph.blocks().size(), 2U);
    EXPECT_EQ(graph.connections().size(), 2U);
    EXPECT_EQ(waysFrom(graph, {2, End::A}), std::vector<std::string>{"1b"});
    EXPECT_TRUE(graph.problems().empty());
}

TEST(TrackGraphPages, AnOverviewThatDisagreesIsReportedAtItsContacts) {
    // The overview puts contact 7 between 5 and 6, which the detail pages join directly.
    const TrackGraph graph = derived({strecke(), bahnhof(), overview({5, 7, 6})});
    ASSERT_EQ(graph.blocks().size(), 3U);
    std::vector<std::string> problems;
    for (const Problem& problem : graph.problems()) {
        EXPECT_EQ(problem.kind, ProblemKind::DrawingsDisagree);
        EXPECT_EQ(placeOf(graph, problem.tile).page, 2);
        problems.push_back(problem.text);
    }
    EXPECT_EQ(problems,
              (std::vector<std::string>{
                  "Contact 5 is also drawn at page 'Strecke', column 2, row 0, and the drawings differ: "
                  "here it lies between a buffer stop and 'Block 7', there between a buffer stop and "
                  "'Gleis'; make the pages agree.",
                  "Contact 6 is also drawn at page 'Bahnhof', column 2, row 0, and the drawings differ: "
                  "here it lies between 'Block 7' and a buffer stop, there between 'Ost' and a buffer "
                  "stop; make the pages agree."}));
}

TEST(TrackGraphPages, AnOverviewWithOtherContactsInTheBlockIsReported) {
    DrawnPage detail(0, "Bahnhof");
    detail.bufferStop(0, 0, true).contact(1, 0, 5).contact(2, 0, 6).bufferStop(3, 0, false);
    DrawnPage brief(1, "Übersicht");
    brief.bufferStop(0, 0, true).contact(1, 0, 5).bufferStop(2, 0, false);
    const TrackGraph graph = derived({detail, brief});
    ASSERT_EQ(graph.blocks().size(), 1U);
    EXPECT_EQ(contactNumbers(graph.block(1)), (std::vector<std::int64_t>{5, 6}));
    ASSERT_EQ(graph.problems().size(), 1U);
    EXPECT_EQ(
        graph.problems()[0].text,
        "Contact 5 is also drawn at page 'Bahnhof', column 1, row 0, and the drawings differ: here its block "
        "holds contacts 5, there 5, 6; make the pages agree.");
}

TEST(TrackGraphPages, AContactOnlyTheOverviewShowsIsPlacedAlongTheFirstDrawing) {
    DrawnPage detail(0, "Bahnhof");
    detail.bufferStop(0, 0, true).contact(1, 0, 5).straight(2, 3, 0).bufferStop(4, 0, false);
    DrawnPage brief(1, "Übersicht");
    brief.bufferStop(0, 0, true).contact(1, 0, 5).contact(2, 0, 6).bufferStop(3, 0, false);
    const TrackGraph graph = derived({detail, brief});
    ASSERT_EQ(graph.blocks().size(), 1U);
    const Block& block = graph.block(1);
    ASSERT_EQ(contactNumbers(block), (std::vector<std::int64_t>{5, 6}));
    // On the overview contact 6 covers 270..450 of 540 mm; the detail drawing is 720 mm long.
    EXPECT_EQ(block.contacts[1].fromMm, 360);
    EXPECT_EQ(block.contacts[1].toMm, 600);
    EXPECT_EQ(countProblems(graph, ProblemKind::DrawingsDisagree), 1U);
}

namespace {

// The turnout fan of TrackGraphTest on an overview page: the same contacts and turnout 5; `swapped` draws
// its straight leg to contact 3 and its diverging leg to contact 2.
DrawnPage fanOverview(bool swapped) {
    DrawnPage page(1, "Übersicht");
    page.bufferStop(0, 1, true).contact(1, 1, 1).accessory(2, 1, "linksweiche", 3, 5);
    page.straight(3, 3, 1).contact(4, 1, swapped ? 3 : 2).bufferStop(5, 1, false);
    page.tile(2, 0, "bogen").contact(3, 0, swapped ? 2 : 3).bufferStop(4, 0, false);
    return page;
}

DrawnPage fanDetail() {
    DrawnPage page(0, "Bahnhof");
    page.bufferStop(0, 1, true).contact(1, 1, 1, "Zufahrt").accessory(2, 1, "linksweiche", 3, 5);
    page.straight(3, 3, 1).contact(4, 1, 2, "Gerade").bufferStop(5, 1, false);
    page.tile(2, 0, "bogen").contact(3, 0, 3, "Abzweig").bufferStop(4, 0, false);
    return page;
}

} // namespace

TEST(TrackGraphPages, ATurnoutDrawnOnTwoPagesIsOneTurnout) {
    const TrackGraph graph = derived({fanDetail(), fanOverview(false)});
    EXPECT_EQ(graph.blocks().size(), 3U);
    EXPECT_EQ(graph.connections().size(), 4U); // the overview's ways are the detail's
    EXPECT_TRUE(graph.problems().empty());
}

TEST(TrackGraphPages, ATurnoutWhoseDrawingsLeadElsewhereIsReported) {
    const TrackGraph graph = derived({fanDetail(), fanOverview(true)});
    ASSERT_EQ(graph.problems().size(), 1U);
    const Problem& problem = graph.problems()[0];
    EXPECT_EQ(problem.kind, ProblemKind::DrawingsDisagree);
    EXPECT_EQ(placeOf(graph, problem.tile), (TilePlace{1, 2, 1}));
    EXPECT_EQ(problem.text,
              "Turnout 5 is also drawn at page 'Bahnhof', column 2, row 1, and the drawings differ: "
              "here it joins 'Abzweig' and 'Zufahrt' straight, 'Zufahrt' and 'Gerade' diverging, "
              "there it joins 'Abzweig' and 'Zufahrt' diverging, 'Zufahrt' and 'Gerade' straight; "
              "make the pages agree.");
}
