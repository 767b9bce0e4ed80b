// The layout in use (issue 33): where it came from, its files, its graph derived once per change, opening
// a folder without losing the layout in use on a bad one, and an export that gives the files back.

#include "model/LayoutInUse.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace stellwerk::model {
namespace {

namespace fs = std::filesystem;

fs::path demoFolder() {
    return fs::path(STELLWERK_SOURCE_DIR) / "resources/demo-layout";
}

fs::path corpusFolder() {
    return fs::path(STELLWERK_SHARED_DIR) / "corpus/GBert__railroad/can2udp/files/maerklin";
}

std::string bytesOf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

// What a station's start-up hands over for the demo layout: its plan, pages, accessories, routes and the
// locomotive file as downloaded.
station::StartupResult demoDownload() {
    const cs2config::LayoutFolder::Content demo = cs2config::LayoutFolder::open(demoFolder());
    station::StartupResult result;
    result.trackPlan = demo.layout.plan;
    for (const cs2config::TrackLayoutPage& page : demo.layout.pages)
        result.pages.push_back({page.id, page.name, page.page});
    result.accessories = demo.accessories;
    result.files["loks"] = bytesOf(demoFolder() / "config/lokomotive.cs2");
    return result;
}

TEST(LayoutInUse, NothingIsInUseAtFirst) {
    const LayoutInUse layout;
    EXPECT_EQ(layout.origin(), LayoutInUse::Origin::None);
    EXPECT_EQ(layout.pages(), nullptr);
    EXPECT_EQ(layout.graph(), nullptr);
    EXPECT_FALSE(layout.hasPlan());
}

TEST(LayoutInUse, AnOpenedFolderSaysWhereItCameFromWithItsFilesGraphAndPictures) {
    LayoutInUse layout;
    QSignalSpy changed(&layout, &LayoutInUse::changed);
    ASSERT_EQ(layout.open(demoFolder()), "");
    EXPECT_EQ(changed.count(), 1);
    EXPECT_EQ(layout.origin(), LayoutInUse::Origin::Folder);
    EXPECT_EQ(layout.folder(), demoFolder() / "config");
    EXPECT_EQ(layout.picturesFolder(), demoFolder() / "icons");
    ASSERT_NE(layout.pages(), nullptr);
    EXPECT_EQ(layout.pages()->pages().size(), 3U);
    ASSERT_NE(layout.routes(), nullptr) << "fahrstrassen.cs2 is read beside the plan";
    EXPECT_EQ(layout.accessoryName(1), "W1 Einfahrt West");
    ASSERT_NE(layout.graph(), nullptr);
    EXPECT_EQ(layout.graph()->blocks().size(), 9U);
}

TEST(LayoutInUse, TheGraphIsDerivedOncePerLayoutAndAgainForAnother) {
    LayoutInUse layout;
    ASSERT_EQ(layout.open(demoFolder()), "");
    const std::shared_ptr<const trackgraph::TrackGraph> graph = layout.graph();
    EXPECT_EQ(layout.graph(), graph) << "asking again derives nothing";
    EXPECT_EQ(layout.pages(), layout.pages());
    ASSERT_EQ(layout.open(corpusFolder()), "");
    EXPECT_NE(layout.graph(), graph) << "another layout, another graph";
    EXPECT_EQ(layout.graph()->pages().size(), layout.pages()->pages().size());
}

TEST(LayoutInUse, ABadFolderLeavesTheLayoutInUseAsItWas) {
    LayoutInUse layout;
    ASSERT_EQ(layout.open(demoFolder()), "");
    const auto pages = layout.pages();
    const auto graph = layout.graph();
    QSignalSpy changed(&layout, &LayoutInUse::changed);
    QTemporaryDir empty;
    const std::string problem = layout.open(empty.path().toStdString());
    EXPECT_FALSE(problem.empty());
    EXPECT_FALSE(layout.open("/nonexistent/layout").empty());
    EXPECT_EQ(changed.count(), 0);
    EXPECT_EQ(layout.origin(), LayoutInUse::Origin::Folder);
    EXPECT_EQ(layout.folder(), demoFolder() / "config");
    EXPECT_EQ(layout.pages(), pages);
    EXPECT_EQ(layout.graph(), graph);
}

TEST(LayoutInUse, AnExportOfAnOpenedCorpusFolderGivesItsFilesBackByteForByte) {
    LayoutInUse layout;
    ASSERT_EQ(layout.open(corpusFolder()), "");
    QTemporaryDir target;
    const fs::path folder = fs::path(target.path().toStdString()) / "new/layout";
    ASSERT_EQ(layout.exportTo(folder), "") << "the folder is made";
    const fs::path from = corpusFolder() / "config";
    int compared = 0;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(from)) {
        if (!entry.is_regular_file())
            continue;
        const fs::path inside = fs::relative(entry.path(), from);
        EXPECT_EQ(bytesOf(folder / "config" / inside), bytesOf(entry.path())) << inside;
        ++compared;
    }
    EXPECT_GE(compared, 4);
}

TEST(LayoutInUse, TheStationsDownloadIsInUseUntilAFolderIsOpened) {
    LayoutInUse layout;
    QSignalSpy changed(&layout, &LayoutInUse::changed);
    layout.useStationDownload(demoDownload());
    EXPECT_EQ(changed.count(), 1);
    EXPECT_EQ(layout.origin(), LayoutInUse::Origin::Station);
    EXPECT_EQ(layout.folder(), fs::path());
    EXPECT_EQ(layout.picturesFolder(), fs::path()) << "the station's pictures come from the station";
    ASSERT_NE(layout.graph(), nullptr);
    EXPECT_EQ(layout.graph()->blocks().size(), 9U);

    ASSERT_EQ(layout.open(corpusFolder()), "");
    const auto opened = layout.pages();
    changed.clear();
    layout.useStationDownload(demoDownload()); // the station started up again
    EXPECT_EQ(changed.count(), 0) << "the opened folder wins";
    EXPECT_EQ(layout.pages(), opened);

    layout.showStation();
    EXPECT_EQ(changed.count(), 1);
    EXPECT_EQ(layout.origin(), LayoutInUse::Origin::Station);
    EXPECT_EQ(layout.pages()->pages().size(), 3U);
    layout.forgetStation();
    EXPECT_EQ(changed.count(), 2);
    EXPECT_EQ(layout.origin(), LayoutInUse::Origin::None);
}

TEST(LayoutInUse, EveryNewDownloadIsAnotherLayout) {
    LayoutInUse layout;
    layout.useStationDownload(demoDownload());
    const auto graph = layout.graph();
    QSignalSpy changed(&layout, &LayoutInUse::changed);
    layout.useStationDownload(demoDownload());
    EXPECT_EQ(changed.count(), 1);
    EXPECT_NE(layout.graph(), graph);
}

TEST(LayoutInUse, AnExportOfTheStationsDownloadWritesItsPlanAndFiles) {
    LayoutInUse layout;
    layout.useStationDownload(demoDownload());
    QTemporaryDir target;
    ASSERT_EQ(layout.exportTo(target.path().toStdString()), "");
    const fs::path config = fs::path(target.path().toStdString()) / "config";
    EXPECT_EQ(bytesOf(config / "lokomotive.cs2"), bytesOf(demoFolder() / "config/lokomotive.cs2"));
    EXPECT_EQ(bytesOf(config / "gleisbild.cs2"), bytesOf(demoFolder() / "config/gleisbild.cs2"));
    LayoutInUse again;
    ASSERT_EQ(again.open(target.path().toStdString()), "");
    EXPECT_EQ(again.graph()->blocks().size(), 9U);
}

TEST(LayoutInUse, WithoutAPlanThereIsNothingToExportAndNoFolderIsMade) {
    LayoutInUse layout;
    layout.useStationDownload(station::StartupResult{});
    EXPECT_EQ(layout.origin(), LayoutInUse::Origin::Station);
    EXPECT_FALSE(layout.hasPlan());
    EXPECT_EQ(layout.graph(), nullptr);
    QTemporaryDir target;
    const fs::path folder = fs::path(target.path().toStdString()) / "export";
    EXPECT_FALSE(layout.exportTo(folder).empty());
    EXPECT_FALSE(fs::exists(folder));
}

} // namespace
} // namespace stellwerk::model
