// The demo layout that ships in resources/demo-layout: clean files, embedded as a Qt resource, and a
// track plan whose tiles point at things that exist.

#include "cs2config/ConfigFile.h"
#include "cs2config/RouteAccessoryCheck.h"
#include "sim/StationLayout.h"
#include "sim/TrainTrack.h"

#include <QFile>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <set>
#include <sstream>
#include <string>
#include <utility>

namespace stellwerk::sim {
namespace {

using cs2config::ConfigFile;
using cs2config::ConfigKind;

const std::filesystem::path SourceDir = STELLWERK_DEMO_LAYOUT_DIR;

struct DemoFile {
    std::string path;
    ConfigKind kind;
};

const std::vector<DemoFile> DemoFiles = {
    {"lokomotive.cs2", ConfigKind::Locomotives},        {"magnetartikel.cs2", ConfigKind::Accessories},
    {"fahrstrassen.cs2", ConfigKind::Routes},           {"gleisbild.cs2", ConfigKind::TrackPlan},
    {"gleisbilder/Bahnhof.cs2", ConfigKind::TrackPage}, {"gleisbilder/Strecke.cs2", ConfigKind::TrackPage},
    {"gleisbilder/Bw.cs2", ConfigKind::TrackPage},
};

std::string sourceBytes(const std::string& path) {
    std::ifstream in(SourceDir / path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

std::string resourceBytes(const std::string& path) {
    QFile file(QString::fromStdString(std::string(StationLayout::demoResource) + path));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return file.readAll().toStdString();
}

const StationLayout& demo() {
    static const StationLayout layout = StationLayout::demo();
    return layout;
}

TEST(DemoLayout, EveryFilePassesCs2CheckWithoutAnyDiagnostic) {
    for (const DemoFile& demoFile : DemoFiles) {
        const ConfigFile file = ConfigFile::load(SourceDir / demoFile.path);
        EXPECT_EQ(file.kind(), demoFile.kind) << demoFile.path;
        EXPECT_TRUE(file.diagnostics().empty()) << file.diagnostics().formatAll();
    }
}

TEST(DemoLayout, IsEmbeddedAsQtResourceWithTheSourceBytes) {
    for (const DemoFile& demoFile : DemoFiles) {
        const std::string embedded = resourceBytes(demoFile.path);
        EXPECT_FALSE(embedded.empty()) << demoFile.path << " is not in :/demo-layout/config/";
        EXPECT_EQ(embedded, sourceBytes(demoFile.path)) << demoFile.path;
    }
}

TEST(DemoLayout, StationLayoutDemoFindsEveryFileByPathAndKey) {
    EXPECT_TRUE(demo().diagnostics().empty()) << demo().diagnostics().front();
    for (const DemoFile& demoFile : DemoFiles) {
        const std::optional<std::string> served = demo().fileForPath(demoFile.path);
        ASSERT_TRUE(served) << demoFile.path;
        EXPECT_EQ(*served, sourceBytes(demoFile.path));
    }
    for (const char* key : {"loks", "mags", "fs", "gbs", "gbs-0", "gbs-1", "gbs-2"})
        EXPECT_TRUE(demo().fileForKey(key)) << key;
    ASSERT_EQ(demo().trackPlan().pages.size(), 3U);
    for (const cs2config::TrackLayoutPage& page : demo().trackPlan().pages)
        EXPECT_FALSE(page.page.elements.empty()) << page.name;
}

TEST(DemoLayout, LocomotivesCoverEveryProtocolWithFunctions) {
    const auto& locomotives = demo().locomotives().locomotives;
    EXPECT_EQ(locomotives.size(), 12U);
    std::set<cs2config::LocomotiveDecoder> decoders;
    bool momentary = false;
    for (const cs2config::Locomotive& loco : locomotives) {
        decoders.insert(loco.decoder);
        EXPECT_FALSE(loco.functions.empty()) << loco.name;
        EXPECT_NE(loco.functions.front().icon, 0) << loco.name << ": F0 has no icon";
        momentary =
            momentary || std::ranges::any_of(loco.functions, [](const auto& f) { return f.icon >= 128; });
    }
    using D = cs2config::LocomotiveDecoder;
    EXPECT_EQ(decoders, (std::set<D>{D::Mfx, D::Mm2Prg, D::Mm2Dil8, D::Dcc}));
    EXPECT_TRUE(momentary) << "no momentary function (icon + 128)";
}

// Field notes: an accessory tile's .artikel is 2 x the article's .id, plus 1 for the second output of a
// paired one-output article (.ungerade=1).
bool accessoryExists(std::int64_t article) {
    const auto& accessories = demo().accessories().accessories;
    return std::ranges::any_of(accessories, [article](const cs2config::Accessory& accessory) {
        return accessory.id == article / 2 && accessory.secondOutput == (article % 2 == 1);
    });
}

TEST(DemoLayout, TrackPlanTilesLinkToExistingAccessoriesRoutesAndPages) {
    const cs2config::TrackLayout& plan = demo().trackPlan();
    int accessoryTiles = 0;
    for (const cs2config::TrackLayoutPage& page : plan.pages)
        for (const cs2config::TrackElement& element : page.page.elements) {
            EXPECT_EQ(element.position.page, page.id) << page.name << " line " << element.line();
            switch (element.articleLink()) {
            case cs2config::ArticleLink::Accessory:
                ++accessoryTiles;
                EXPECT_TRUE(accessoryExists(element.article)) << page.name << " line " << element.line();
                break;
            case cs2config::ArticleLink::Route:
                EXPECT_NE(demo().routes().find(element.article), nullptr)
                    << page.name << " line " << element.line();
                break;
            case cs2config::ArticleLink::Page:
                EXPECT_NE(plan.plan.pageWithId(element.article), nullptr)
                    << page.name << " line " << element.line();
                break;
            default:
                break;
            }
        }
    EXPECT_EQ(accessoryTiles, int(demo().accessories().accessories.size())); // every article is drawn once
}

TEST(DemoLayout, RoutesSwitchOnlyAccessoriesTheKeyboardHas) {
    EXPECT_GE(demo().routes().routes.size(), 3U);
    cs2config::Diagnostics diagnostics("fahrstrassen.cs2");
    cs2config::checkRouteAccessories(demo().routes(), demo().accessories(), diagnostics);
    EXPECT_TRUE(diagnostics.empty()) << diagnostics.formatAll();
}

TEST(DemoLayout, TrainTrackUsesTheContactsOfThePlanAndItsLocomotives) {
    const TrainTrack track = TrainTrack::demo();
    ASSERT_TRUE(track.consistent());
    std::set<std::pair<std::int64_t, std::int64_t>> drawn;
    for (const cs2config::TrackLayoutPage& page : demo().trackPlan().pages)
        for (const cs2config::TrackElement& element : page.page.elements)
            if (element.articleLink() == cs2config::ArticleLink::FeedbackContact)
                drawn.emplace(element.deviceId, element.article);
    std::set<std::pair<std::int64_t, std::int64_t>> moved;
    for (const FeedbackSection& section : track.sections)
        moved.emplace(section.device, section.contact);
    EXPECT_EQ(moved, drawn);
    for (const TrainPlacement& placement : track.placements)
        EXPECT_TRUE(std::ranges::any_of(demo().locomotives().locomotives,
                                        [&](const auto& loco) { return loco.uid == placement.locId; }))
            << std::hex << placement.locId;
}

TEST(DemoLayout, AnyOtherLayoutRunsTrainsOnALoopOfItsContacts) {
    const TrainTrack track = TrainTrack::loopOfContacts(demo().trackPlan(), {0x4001, 0x18});
    ASSERT_EQ(track.sections.size(), 9U);
    EXPECT_TRUE(track.consistent());
    EXPECT_EQ(track.sections.back().ahead.next, 0);
    EXPECT_EQ(track.sections.front().behind.next, 8);
    ASSERT_EQ(track.placements.size(), 2U);
    EXPECT_NE(track.placements[0].section, track.placements[1].section);
}

} // namespace
} // namespace stellwerk::sim
