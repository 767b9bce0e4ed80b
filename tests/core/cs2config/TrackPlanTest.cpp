#include "cs2config/TrackPlan.h"

#include "ConfigTestSupport.h"

#include <gtest/gtest.h>
#include <tuple>

using namespace stellwerk::cs2config;
using namespace stellwerk::cs2config::test;

namespace {

struct ReadPlan {
    Diagnostics diagnostics;
    TrackPlan plan;
};

ReadPlan readPlanText(std::string_view text) {
    Parsed parsed = parseText(text, "gleisbild.cs2");
    TrackPlan plan = TrackPlan::read(parsed.document, parsed.diagnostics);
    return {std::move(parsed.diagnostics), std::move(plan)};
}

ReadPlan readCorpusPlan(std::string_view file) {
    return readPlanText(readCorpus(file));
}

using PageList = std::vector<std::pair<std::int64_t, std::string>>;

PageList pageList(const TrackPlan& plan) {
    PageList list;
    for (const TrackPageEntry& page : plan.pages)
        list.emplace_back(page.id, page.name);
    return list;
}

TrackPageEntry newPage(std::int64_t id, std::string name) {
    TrackPageEntry page;
    page.id = id;
    page.name = std::move(name);
    return page;
}

std::vector<std::string> planMessages(const Diagnostics& diagnostics) {
    std::vector<std::string> texts;
    for (const Diagnostic& diagnostic : diagnostics.items())
        texts.push_back(diagnostics.format(diagnostic));
    return texts;
}

// Document 8.3, "Grundformat", as printed.
constexpr std::string_view documentExample = "[gleisbild]\n"
                                             "version\n"
                                             "  .major=0\n"
                                             "  .minor=6\n"
                                             "groesse\n"
                                             "  .width=20\n"
                                             "  .height=15\n"
                                             "zuletztBenutzt\n"
                                             "  .name=Haupt-alt\n"
                                             "seite\n"
                                             "  .id=0\n"
                                             "  .name=Haupt-alt\n"
                                             "seite\n"
                                             "  .id=1\n"
                                             "  .name=Hauptbahnhof\n"
                                             "element\n"
                                             "  .id=0x301\n"
                                             "  .typ=s88kontakt\n"
                                             "  .drehung=0\n"
                                             "  .artikel=2\n"
                                             "  .text=\n";

} // namespace

TEST(TrackPlan, DocumentExample) {
    const auto [diagnostics, plan] = readPlanText(documentExample);
    EXPECT_TRUE(diagnostics.empty()) << diagnostics.formatAll();
    EXPECT_EQ(plan.version, (TrackFileVersion{0, 6}));
    EXPECT_EQ(plan.size, (TrackGridSize{20, 15}));
    EXPECT_EQ(plan.lastUsedPage, "Haupt-alt");
    EXPECT_EQ(pageList(plan), (PageList{{0, "Haupt-alt"}, {1, "Hauptbahnhof"}}));
    ASSERT_NE(plan.lastUsed(), nullptr);
    EXPECT_EQ(plan.lastUsed()->id, 0);
    ASSERT_EQ(plan.elements.size(), 1u);
    const TrackElement& contact = plan.elements[0];
    EXPECT_EQ(contact.position, (TrackPosition{0, 1, 3}));
    EXPECT_EQ(contact.type, "s88kontakt");
    EXPECT_EQ(contact.category(), TrackCategory::Feedback);
    EXPECT_EQ(contact.rotation, 0);
    EXPECT_EQ(contact.article, 2);
    EXPECT_EQ(contact.text, "");
    EXPECT_EQ(plan.write().serialize(), documentExample);
}

// Document 8.3.3 names the field `.seite=0` ("Name der Seite"); real files write `.name=<page name>`.
TEST(TrackPlan, DocumentLastUsedPageField) {
    const std::string text = "[gleisbild]\nzuletztBenutzt\n .seite=0\nseite\n .name=Seite0\nseite\n .id=1\n"
                             " .name=Seite1\n";
    auto [diagnostics, plan] = readPlanText(text);
    EXPECT_TRUE(diagnostics.empty()) << diagnostics.formatAll();
    EXPECT_EQ(plan.lastUsedPage, "0");
    ASSERT_NE(plan.lastUsed(), nullptr);
    EXPECT_EQ(plan.lastUsed()->name, "Seite0");
    plan.lastUsedPage = "1";
    const std::string written = plan.write().serialize();
    EXPECT_EQ(written,
              "[gleisbild]\nzuletztBenutzt\n .seite=1\nseite\n .name=Seite0\nseite\n .id=1\n .name=Seite1\n");
    EXPECT_EQ(readPlanText(written).plan.lastUsed()->name, "Seite1");
}

TEST(TrackPlan, GbertIndex) {
    const auto [diagnostics, plan] = readCorpusPlan(corpus::gleisbildGbert);
    EXPECT_TRUE(diagnostics.empty()) << diagnostics.formatAll();
    EXPECT_EQ(plan.version, (TrackFileVersion{1, 0}));
    // `groesse` is there but empty.
    EXPECT_EQ(plan.size, TrackGridSize{});
    EXPECT_EQ(pageList(plan), (PageList{{0, "karben"}}));
    EXPECT_FALSE(plan.pages[0].source.find("id")); // the page has no `.id`: implicit 0
    EXPECT_EQ(plan.lastUsedPage, "karben");
    EXPECT_EQ(plan.lastUsed(), &plan.pages[0]);
    EXPECT_TRUE(plan.elements.empty());
}

TEST(TrackPlan, MrFlexiIndexWithElevenPages) {
    const auto [diagnostics, plan] = readCorpusPlan(corpus::gleisbildMrFlexi);
    EXPECT_TRUE(diagnostics.empty()) << diagnostics.formatAll();
    ASSERT_EQ(plan.pages.size(), 11u);
    EXPECT_EQ(plan.pages[0].id, 0);
    EXPECT_EQ(plan.pages[0].name, "Tastenmatrix");
    for (std::size_t i = 0; i < plan.pages.size(); ++i)
        EXPECT_EQ(plan.pages[i].id, static_cast<std::int64_t>(i));
    EXPECT_EQ(plan.pages[10].name, "Strecke");
    EXPECT_EQ(plan.lastUsedPage, "Wendel");
    ASSERT_NE(plan.lastUsed(), nullptr);
    EXPECT_EQ(plan.lastUsed()->id, 5);
}

TEST(TrackPlan, TrainControlSampleIndex) {
    const auto [diagnostics, plan] = readCorpusPlan(corpus::gleisbildSample);
    EXPECT_TRUE(diagnostics.empty()) << diagnostics.formatAll();
    EXPECT_EQ(pageList(plan), (PageList{{0, "1 - Main"},
                                        {2, "2 - Bottom"},
                                        {3, "3 - Top Parking"},
                                        {4, "4 - Combined"},
                                        {5, "5 - Test"}}));
    EXPECT_FALSE(plan.lastUsedPage);
    EXPECT_EQ(plan.lastUsed(), nullptr);
    EXPECT_EQ(plan.pageNamed("3 - Top Parking"), plan.pageWithId(3));
    EXPECT_EQ(plan.pageWithId(1), nullptr);
}

TEST(TrackPlan, UnchangedModelWritesTheOriginalBytes) {
    for (const std::string_view file :
         {corpus::gleisbildGbert, corpus::gleisbildMrFlexi, corpus::gleisbildSample, corpus::cs3TrackPlan}) {
        const std::string bytes = readCorpus(file);
        EXPECT_EQ(readPlanText(bytes).plan.write().serialize(), bytes) << file;
    }
}

TEST(TrackPlan, RenamingAPageChangesOneLine) {
    const std::string bytes = readCorpus(corpus::gleisbildMrFlexi);
    TrackPlan plan = readPlanText(bytes).plan;
    plan.pages[3].name = "Eschenhofen Bf";
    const std::string written = plan.write().serialize();
    std::string expected = bytes;
    expected.replace(expected.find(" .name=Eschenhofen\n"), 19, " .name=Eschenhofen Bf\n");
    EXPECT_EQ(written, expected);
}

TEST(TrackPlan, SizeAndLastUsedPageAreWritten) {
    const std::string bytes = readCorpus(corpus::gleisbildGbert);
    TrackPlan plan = readPlanText(bytes).plan;
    plan.size = TrackGridSize{20, 15};
    plan.lastUsedPage = "Bahnhof";
    plan.pages.push_back(newPage(1, "Bahnhof"));
    EXPECT_EQ(plan.write().serialize(), "[gleisbild]\nversion\n .major=1\ngroesse\n .width=20\n .height=15\n"
                                        "zuletztBenutzt\n .name=Bahnhof\nseite\n .name=karben\n"
                                        "seite\n .id=1\n .name=Bahnhof\n");
    plan.size->width.reset();
    plan.lastUsedPage.reset();
    EXPECT_EQ(plan.write().serialize(), "[gleisbild]\nversion\n .major=1\ngroesse\n .height=15\n"
                                        "seite\n .name=karben\nseite\n .id=1\n .name=Bahnhof\n");
}

TEST(TrackPlan, AddAndRemovePages) {
    const std::string bytes = readCorpus(corpus::gleisbildSample);
    TrackPlan plan = readPlanText(bytes).plan;
    plan.pages.erase(plan.pages.begin() + 1);
    plan.pages.push_back(newPage(6, "6 - Yard"));
    const auto [diagnostics, reread] = readPlanText(plan.write().serialize());
    EXPECT_TRUE(diagnostics.empty()) << diagnostics.formatAll();
    EXPECT_EQ(
        pageList(reread),
        (PageList{
            {0, "1 - Main"}, {3, "3 - Top Parking"}, {4, "4 - Combined"}, {5, "5 - Test"}, {6, "6 - Yard"}}));
}

TEST(TrackPlan, NewIndexWrittenTheWayACs2WritesOne) {
    TrackPlan plan;
    plan.lastUsedPage = "Main";
    plan.pages.push_back(newPage(0, "Main"));
    plan.pages.push_back(newPage(1, "Yard"));
    const std::string written = plan.write().serialize();
    EXPECT_EQ(written, "[gleisbild]\nversion\n .major=1\ngroesse\nzuletztBenutzt\n .name=Main\n"
                       "seite\n .name=Main\nseite\n .id=1\n .name=Yard\n");
    const auto [diagnostics, reread] = readPlanText(written);
    EXPECT_TRUE(diagnostics.empty()) << diagnostics.formatAll();
    EXPECT_EQ(pageList(reread), pageList(plan));
    EXPECT_EQ(reread.size, TrackGridSize{});
    EXPECT_EQ(reread.lastUsed()->name, "Main");
}

TEST(TrackPlan, PageProblemsAreReported) {
    const auto [diagnostics, plan] = readPlanText(
        "[gleisbild]\nzuletztBenutzt\n .name=Gone\nseite\n .name=A\nseite\n .name=B\nseite\n .id=2\n"
        "seite\n .id=x\n .name=A\n");
    EXPECT_EQ(pageList(plan), (PageList{{0, "A"}, {0, "B"}, {2, ""}, {0, "A"}}));
    const std::vector<std::string> texts = planMessages(diagnostics);
    ASSERT_EQ(texts.size(), 6u) << diagnostics.formatAll();
    EXPECT_EQ(texts[0],
              "gleisbild.cs2:6: warning: second page with id 0 (also line 4); a page without .id counts "
              "as 0; both are kept");
    EXPECT_EQ(texts[1], "gleisbild.cs2:8: warning: page 2 without .name; kept; it has no page file to load");
    EXPECT_EQ(texts[2],
              "gleisbild.cs2:11: warning: page .id 'x' is not a number; 0 used; the line is kept as it is");
    EXPECT_EQ(texts[3],
              "gleisbild.cs2:10: warning: second page named 'A' (also line 4); both are kept; they share "
              "one page file");
    EXPECT_EQ(texts[4], "gleisbild.cs2:10: warning: second page with id 0 (also line 4); both are kept");
    EXPECT_EQ(texts[5],
              "gleisbild.cs2:2: warning: last used page 'Gone' is not in the page list; kept; no page "
              "is shown first");
}

TEST(TrackPlan, RecordProblemsAreReported) {
    const auto [diagnostics, plan] =
        readPlanText("[gleisbild]\nversion\n .major=1\ngroesse\n .width=999\n .tiefe=3\n"
                     "version\n .major=2\nlayer\nlayer\n");
    EXPECT_EQ(plan.version, (TrackFileVersion{1, 0}));
    EXPECT_EQ(plan.size, TrackGridSize{});
    const std::vector<std::string> texts = planMessages(diagnostics);
    ASSERT_EQ(texts.size(), 4u) << diagnostics.formatAll();
    EXPECT_EQ(texts[0],
              "gleisbild.cs2:7: warning: second 'version' record; the first one is used; both are kept");
    EXPECT_EQ(texts[1], "gleisbild.cs2:9: warning: unknown record 'layer' (reported once); kept unchanged");
    EXPECT_EQ(texts[2],
              "gleisbild.cs2:6: warning: unknown groesse key .tiefe (reported once); kept unchanged");
    EXPECT_EQ(texts[3],
              "gleisbild.cs2:5: warning: groesse .width 999 is outside 1..256; ignored; the line is kept "
              "as it is");
}

TEST(TrackPlan, Cs3TrackPlanIsRefusedClearly) {
    const auto [diagnostics, plan] = readCorpusPlan(corpus::cs3TrackPlan);
    EXPECT_EQ(plan.format, TrackPlanFormat::Cs3Pixels);
    EXPECT_TRUE(plan.pages.empty());
    EXPECT_TRUE(plan.elements.empty());
    ASSERT_EQ(diagnostics.items().size(), 1u) << diagnostics.formatAll();
    EXPECT_TRUE(diagnostics.hasErrors());
    EXPECT_EQ(
        diagnostics.items()[0].message.rfind("CS3 track plan format (pixel coordinates) is not supported", 0),
        0u);
}

TEST(TrackPlan, Json) {
    const std::string json = toJson(readCorpusPlan(corpus::gleisbildMrFlexi).plan);
    EXPECT_NE(json.find("\"lastUsedPage\": \"Wendel\""), std::string::npos) << json;
    EXPECT_NE(json.find("\"size\": {\n    \"width\": null,\n    \"height\": null\n  }"), std::string::npos)
        << json;
    EXPECT_NE(json.find("\"id\": 10,\n      \"name\": \"Strecke\""), std::string::npos) << json;
}
