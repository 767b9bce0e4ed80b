#include "cs2config/LayoutFolder.h"

#include "ConfigTestSupport.h"

#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace stellwerk::cs2config;
using namespace stellwerk::cs2config::test;
namespace fs = std::filesystem;

namespace {

// The CS2 folder of the can2udp corpus: config/gleisbild.cs2, gleisbilder/karben.cs2, magnetartikel.cs2.
fs::path gbertFolder() {
    return corpusPath(corpus::gleisbildGbert).parent_path().parent_path();
}

std::string fileText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

} // namespace

TEST(LayoutFolder, OpensACs2FolderWithItsPagesAndArticleNames) {
    const LayoutFolder::Content content = LayoutFolder::open(gbertFolder());
    ASSERT_EQ(content.problem, "");
    EXPECT_EQ(content.configDirectory, gbertFolder() / "config");
    ASSERT_EQ(content.layout.pages.size(), 1U);
    EXPECT_EQ(content.layout.pages[0].name, "karben");
    EXPECT_TRUE(content.layout.pages[0].loaded);
    EXPECT_EQ(content.layout.pages[0].page.elements.size(), 37U);
    ASSERT_TRUE(content.accessories);
    EXPECT_EQ(content.accessories->accessories.size(), 13U);
}

TEST(LayoutFolder, TheConfigFolderItselfOpensToo) {
    const LayoutFolder::Content content = LayoutFolder::open(gbertFolder() / "config");
    EXPECT_EQ(content.problem, "");
    EXPECT_EQ(content.layout.pages.size(), 1U);
}

TEST(LayoutFolder, AMissingFolderSaysSo) {
    const LayoutFolder::Content content = LayoutFolder::open("/nonexistent/stellwerk-layout");
    EXPECT_EQ(content.problem, "the folder /nonexistent/stellwerk-layout does not exist");
}

TEST(LayoutFolder, AFolderWithoutTrackPlanSaysSo) {
    QTemporaryDir empty;
    const LayoutFolder::Content content = LayoutFolder::open(empty.path().toStdString());
    EXPECT_NE(content.problem.find(
                  "there is no track plan (config/gleisbild.cs2, or pages in config/gleisbilder/)"),
              std::string::npos);
}

TEST(LayoutFolder, AMissingPageFileLeavesThatPageEmptyAndTheOthersLoaded) {
    // The sample layout lists five pages but ships one page file.
    const fs::path folder = corpusPath(corpus::gleisbildSample).parent_path().parent_path();
    const LayoutFolder::Content content = LayoutFolder::open(folder);
    ASSERT_EQ(content.problem, "");
    ASSERT_EQ(content.layout.pages.size(), 5U);
    int loaded = 0;
    for (const TrackLayoutPage& page : content.layout.pages)
        loaded += page.loaded ? 1 : 0;
    EXPECT_EQ(loaded, 1);
    EXPECT_NE(content.layout.diagnostics.formatAll().find("is missing"), std::string::npos);
}

namespace {

// A copy of the can2udp folder without its gleisbild.cs2, with karben.cs2 also as "10 - Hafen" and
// "2 - Bahnhof", and magnetartikel.cs2 for the names.
fs::path folderWithoutIndex(const QTemporaryDir& target) {
    const fs::path config = fs::path(target.path().toStdString()) / "config";
    const fs::path source = gbertFolder() / "config";
    fs::create_directories(config / "gleisbilder");
    for (const char* name : {"karben.cs2", "10 - Hafen.cs2", "2 - Bahnhof.cs2"})
        fs::copy_file(source / "gleisbilder" / "karben.cs2", config / "gleisbilder" / name);
    fs::copy_file(source / "magnetartikel.cs2", config / "magnetartikel.cs2");
    return config.parent_path();
}

} // namespace

// Issue 32: a folder whose gleisbild.cs2 is missing was refused ("there is no track plan"), although its
// pages were there. They are shown as a person would number them, and the index is reported missing.
TEST(LayoutFolder, WithoutItsIndexThePagesFoundAreOpenedInTheOrderOfTheirNames) {
    QTemporaryDir target;
    const fs::path folder = folderWithoutIndex(target);
    const LayoutFolder::Content content = LayoutFolder::open(folder);
    ASSERT_EQ(content.problem, "");
    EXPECT_EQ(content.extent, LayoutFolder::Extent::PagesOnly);
    EXPECT_EQ(content.configDirectory, folder / "config");
    ASSERT_EQ(content.layout.pages.size(), 3U);
    EXPECT_EQ(content.layout.pages[0].name, "2 - Bahnhof");
    EXPECT_EQ(content.layout.pages[1].name, "10 - Hafen");
    EXPECT_EQ(content.layout.pages[2].name, "karben");
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(content.layout.pages[i].id, std::int64_t(i));
        EXPECT_TRUE(content.layout.pages[i].loaded);
        EXPECT_EQ(content.layout.pages[i].page.elements.size(), 37U);
    }
    EXPECT_EQ(
        content.layout.diagnostics.formatAll(),
        "gleisbild.cs2: warning: the track plan index is missing; the 3 page file(s) in gleisbilder/ are "
        "shown in the order of their names, numbered from 0\n");
    ASSERT_TRUE(content.accessories) << "the article names come from magnetartikel.cs2 as before";
}

TEST(LayoutFolder, AnExportOfPagesWithoutIndexWritesANewIndexForThem) {
    QTemporaryDir source, target;
    const LayoutFolder::Content content = LayoutFolder::open(folderWithoutIndex(source));
    const fs::path folder = target.path().toStdString();
    ASSERT_EQ(LayoutFolder::write(folder, LayoutFolder::filesOf(content.layout.plan, content.layout.pages)),
              "");
    const LayoutFolder::Content again = LayoutFolder::open(folder);
    ASSERT_EQ(again.problem, "");
    EXPECT_EQ(again.extent, LayoutFolder::Extent::Folder);
    ASSERT_EQ(again.layout.pages.size(), 3U);
    EXPECT_EQ(again.layout.pages[1].name, "10 - Hafen");
    EXPECT_EQ(again.layout.pages[1].id, 1);
    EXPECT_FALSE(again.layout.diagnostics.hasErrors()) << again.layout.diagnostics.formatAll();
}

TEST(LayoutFolder, TheGleisbilderFolderItselfOpensItsPages) {
    QTemporaryDir target;
    const fs::path folder = folderWithoutIndex(target);
    const LayoutFolder::Content content = LayoutFolder::open(folder / "config" / "gleisbilder");
    ASSERT_EQ(content.problem, "");
    EXPECT_EQ(content.configDirectory, folder / "config");
    EXPECT_EQ(content.layout.pages.size(), 3U);
}

TEST(LayoutFolder, ASinglePageFileOpensAlone) {
    const LayoutFolder::Content content =
        LayoutFolder::open(gbertFolder() / "config" / "gleisbilder" / "karben.cs2");
    ASSERT_EQ(content.problem, "");
    EXPECT_EQ(content.extent, LayoutFolder::Extent::SinglePage);
    EXPECT_EQ(content.configDirectory, gbertFolder() / "config");
    ASSERT_EQ(content.layout.pages.size(), 1U);
    EXPECT_EQ(content.layout.pages[0].name, "karben");
    EXPECT_EQ(content.layout.pages[0].page.elements.size(), 37U);
    ASSERT_TRUE(content.accessories) << "magnetartikel.cs2 beside gleisbilder/ names the articles";
    EXPECT_EQ(content.layout.diagnostics.formatAll(), "");
}

TEST(LayoutFolder, TheIndexFileOpensItsFolder) {
    const LayoutFolder::Content content = LayoutFolder::open(gbertFolder() / "config" / "gleisbild.cs2");
    ASSERT_EQ(content.problem, "");
    EXPECT_EQ(content.extent, LayoutFolder::Extent::Folder);
    EXPECT_EQ(content.layout.pages.size(), 1U);
}

TEST(LayoutFolder, AFileThatIsNoPageIsRefusedWithWhatItHolds) {
    const LayoutFolder::Content content = LayoutFolder::open(gbertFolder() / "config" / "magnetartikel.cs2");
    EXPECT_NE(content.problem.find("magnetartikel.cs2 is not a page of a track plan (it holds "),
              std::string::npos)
        << content.problem;
}

TEST(LayoutFolder, RoundTripGivesTheCorpusFilesBackByteForByte) {
    const LayoutFolder::Content content = LayoutFolder::open(gbertFolder());
    ConfigFolderFiles files = LayoutFolder::filesOf(content.layout.plan, content.layout.pages);
    files.merge(LayoutFolder::companionFiles(content.configDirectory));
    EXPECT_TRUE(files.contains("magnetartikel.cs2"));
    EXPECT_TRUE(files.contains("lokomotive.cs2"));
    QTemporaryDir target;
    const fs::path folder = target.path().toStdString();
    ASSERT_EQ(LayoutFolder::write(folder, files), "");
    for (const char* name :
         {"gleisbild.cs2", "gleisbilder/karben.cs2", "magnetartikel.cs2", "lokomotive.cs2"})
        EXPECT_EQ(fileText(folder / "config" / name), fileText(gbertFolder() / "config" / name)) << name;
    const LayoutFolder::Content again = LayoutFolder::open(folder);
    ASSERT_EQ(again.problem, "");
    ASSERT_EQ(again.layout.pages.size(), 1U);
    EXPECT_EQ(again.layout.pages[0].page.elements.size(), 37U);
}

TEST(LayoutFolder, AChangedElementIsWrittenAndReadBack) {
    LayoutFolder::Content content = LayoutFolder::open(gbertFolder());
    content.layout.pages[0].page.elements[0].rotation = 3;
    QTemporaryDir target;
    const fs::path folder = target.path().toStdString();
    ASSERT_EQ(LayoutFolder::write(folder, LayoutFolder::filesOf(content.layout.plan, content.layout.pages)),
              "");
    const LayoutFolder::Content again = LayoutFolder::open(folder);
    EXPECT_EQ(again.layout.pages[0].page.elements[0].rotation, 3);
}

TEST(LayoutFolder, WritingAgainReplacesTheOldFolderWhole) {
    QTemporaryDir target;
    const fs::path folder = target.path().toStdString();
    ASSERT_EQ(LayoutFolder::write(folder, {{"gleisbild.cs2", "[gleisbild]\n"}, {"old.cs2", "x"}}), "");
    ASSERT_EQ(LayoutFolder::write(folder, {{"gleisbild.cs2", "[gleisbild]\nversion\n"}}), "");
    EXPECT_EQ(fileText(folder / "config" / "gleisbild.cs2"), "[gleisbild]\nversion\n");
    EXPECT_FALSE(fs::exists(folder / "config" / "old.cs2"));
    int entries = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(folder))
        ++entries;
    EXPECT_EQ(entries, 1); // no temporary or old folder left behind
}

TEST(LayoutFolder, AFailedWriteLeavesTheOldFolderAsItWas) {
    QTemporaryDir target;
    const fs::path folder = target.path().toStdString();
    ASSERT_EQ(LayoutFolder::write(folder, {{"gleisbild.cs2", "old"}}), "");
    // A file where a folder must go: the new tree cannot be written.
    const std::string problem =
        LayoutFolder::write(folder, {{"gleisbild.cs2", "new"}, {"a", "x"}, {"a/b", "y"}});
    EXPECT_NE(problem, "");
    EXPECT_EQ(fileText(folder / "config" / "gleisbild.cs2"), "old");
}

TEST(LayoutFolder, StationFilesGoUnderTheirFileNamesWithoutTrackPlanKeys) {
    const ConfigFolderFiles files = LayoutFolder::stationFiles(
        {{"loks", "L"}, {"mags", "M"}, {"fs", "F"}, {"gbs", "G"}, {"gbs-0", "P"}, {"../x", "?"}});
    EXPECT_EQ(files, (ConfigFolderFiles{
                         {"lokomotive.cs2", "L"}, {"magnetartikel.cs2", "M"}, {"fahrstrassen.cs2", "F"}}));
}
