#include "cs2config/TrackLayout.h"

#include "ConfigTestSupport.h"

#include <gtest/gtest.h>

using namespace stellwerk::cs2config;
using namespace stellwerk::cs2config::test;

namespace {

std::filesystem::path indexPath(std::string_view file) {
    return corpusPath(file);
}

std::vector<std::string> messages(const Diagnostics& diagnostics) {
    std::vector<std::string> texts;
    for (const Diagnostic& diagnostic : diagnostics.items())
        texts.push_back(diagnostics.format(diagnostic));
    return texts;
}

} // namespace

TEST(TrackLayout, PageFileIsNamedAfterThePage) {
    const std::filesystem::path directory = indexPath(corpus::gleisbildSample).parent_path();
    const std::optional<std::filesystem::path> file = trackPageFile(directory, "5 - Test");
    ASSERT_TRUE(file);
    EXPECT_EQ(*file, directory / "gleisbilder" / "5 - Test.cs2");
    EXPECT_EQ(*file, corpusPath(corpus::testPage));
    EXPECT_TRUE(std::filesystem::is_regular_file(*file));
}

TEST(TrackLayout, PageNamesThatCannotBeFileNames) {
    const std::filesystem::path directory = "/layout";
    for (const std::string_view name : {"", ".", "..", "../lokomotive", "a/b", "a\\b", "tab\there"})
        EXPECT_FALSE(trackPageFile(directory, name)) << name;
    EXPECT_TRUE(trackPageFile(directory, "..Abstellgleis"));
    EXPECT_TRUE(trackPageFile(directory, "Bahnhof Süd")->filename() ==
                std::filesystem::path(u8"Bahnhof Süd.cs2"));
}

TEST(TrackLayout, StreamKeyOfAPage) {
    EXPECT_EQ(trackPageStreamKey(0), "gbs-0");
    EXPECT_EQ(trackPageStreamKey(12), "gbs-12");
}

TEST(TrackLayout, GbertLayoutLoadsItsOnePage) {
    const TrackLayout layout = TrackLayout::load(indexPath(corpus::gleisbildGbert));
    EXPECT_TRUE(layout.diagnostics.empty()) << layout.diagnostics.formatAll();
    ASSERT_EQ(layout.pages.size(), 1u);
    const TrackLayoutPage& page = layout.pages[0];
    EXPECT_EQ(page.id, 0);
    EXPECT_EQ(page.name, "karben");
    EXPECT_TRUE(page.loaded);
    EXPECT_EQ(page.file, corpusPath(corpus::karben));
    EXPECT_TRUE(page.diagnostics.empty()) << page.diagnostics.formatAll();
    EXPECT_EQ(page.page.elements.size(), 37u);
    EXPECT_EQ(page.page.area()->columns(), 14);
    EXPECT_EQ(page.page.area()->rows(), 4);
}

// The sample layout ships only the page file of "5 - Test"; the four others are reported as missing.
TEST(TrackLayout, TrainControlSampleLayout) {
    const TrackLayout layout = TrackLayout::load(indexPath(corpus::gleisbildSample));
    ASSERT_EQ(layout.pages.size(), 5u);
    for (std::size_t i = 0; i < 4; ++i)
        EXPECT_FALSE(layout.pages[i].loaded) << layout.pages[i].name;
    const TrackLayoutPage& test = layout.pages[4];
    EXPECT_TRUE(test.loaded);
    EXPECT_EQ(test.id, 5);
    EXPECT_EQ(test.page.elements.size(), 101u);
    EXPECT_EQ(test.diagnostics.items().size(), 4u) << test.diagnostics.formatAll();
    EXPECT_EQ(test.diagnostics.fileName(), "gleisbilder/5 - Test.cs2");
    const std::vector<std::string> texts = messages(layout.diagnostics);
    ASSERT_EQ(texts.size(), 4u) << layout.diagnostics.formatAll();
    EXPECT_EQ(texts[0],
              "gleisbild.cs2:5: warning: page file 'gleisbilder/1 - Main.cs2' of page 0 is missing; "
              "the page is left empty");
    EXPECT_EQ(texts[3], "gleisbild.cs2:13: warning: page file 'gleisbilder/4 - Combined.cs2' of page 4 is "
                        "missing; the page is left empty");
}

TEST(TrackLayout, MrFlexiLayoutHasNoPageFiles) {
    const TrackLayout layout = TrackLayout::load(indexPath(corpus::gleisbildMrFlexi));
    EXPECT_EQ(layout.pages.size(), 11u);
    EXPECT_EQ(layout.diagnostics.items().size(), 11u) << layout.diagnostics.formatAll();
    for (const TrackLayoutPage& page : layout.pages)
        EXPECT_FALSE(page.loaded);
    EXPECT_EQ(layout.plan.lastUsed()->name, "Wendel");
}

TEST(TrackLayout, MissingIndexFile) {
    const TrackLayout layout = TrackLayout::load(corpusPath("no/such/gleisbild.cs2"));
    EXPECT_TRUE(layout.pages.empty());
    ASSERT_EQ(layout.diagnostics.items().size(), 1u);
    EXPECT_TRUE(layout.diagnostics.hasErrors());
    EXPECT_NE(layout.diagnostics.items()[0].message.find("is missing"), std::string::npos);
    EXPECT_EQ(layout.diagnostics.items()[0].action, "no pages are loaded");
}

TEST(TrackLayout, Json) {
    const std::string json = toJson(TrackLayout::load(indexPath(corpus::gleisbildGbert)));
    EXPECT_NE(json.find("\"index\": {"), std::string::npos) << json.substr(0, 600);
    EXPECT_NE(json.find("\"name\": \"karben\",\n      \"file\": "), std::string::npos) << json.substr(0, 900);
    EXPECT_NE(json.find("\"loaded\": true"), std::string::npos);
    EXPECT_NE(json.find("\"type\": \"signal_p_hp012s\""), std::string::npos);
}
