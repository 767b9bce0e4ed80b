// The demo layout that ships in resources/demo-layout: clean files, embedded as a Qt resource, and a
// track plan whose tiles point at things that exist.

#include "cs2config/ConfigFile.h"
#include "cs2config/RouteAccessoryCheck.h"
#include "sim/StationLayout.h"
#include "sim/TrainPlacement.h"
#include "trackgraph/TrackGraph.h"

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

const trackgraph::TrackGraph& demoGraph() {
    static const trackgraph::TrackGraph graph =
        trackgraph::TrackGraph::derive(demo().trackPlan(), &demo().accessories(), &demo().routes());
    return graph;
}

TEST(DemoLayout, TheTrainsStandOnContactsOfThePlanAndAreItsLocomotives) {
    const std::vector<TrainPlacement> placements = demoPlacements();
    ASSERT_EQ(placements.size(), 4U);
    std::set<std::string> blocks;
    for (const TrainPlacement& placement : placements) {
        const std::optional<int> block = demoGraph().blockWithContact({0, placement.contact});
        ASSERT_TRUE(block) << placement.contact;
        blocks.insert(demoGraph().block(*block).name);
        EXPECT_TRUE(std::ranges::any_of(demo().locomotives().locomotives,
                                        [&](const auto& loco) { return loco.uid == placement.locId; }))
            << std::hex << placement.locId;
    }
    EXPECT_EQ(blocks, (std::set<std::string>{"Gleis 1", "Gleis 2", "Block 2", "Abstellgleis"}));
}

// Any other layout: the first three locomotives, train i of n in block 1 + i * blocks / n, facing b.
TEST(DemoLayout, AnyOtherLayoutSpreadsItsFirstLocomotivesOverTheBlocks) {
    const std::vector<TrainPlacement> placements = spreadPlacements(demo().locomotives(), demoGraph());
    ASSERT_EQ(placements.size(), 3U);
    // lokomotive.cs2 begins with BR 218 Ost, V 100 2023, ICE 3 Velaro; blocks 1, 4 and 7 of 9 are Gleis 2
    // (contact 2), Gleis 1 (1) and Block 2 (4).
    EXPECT_EQ(placements, (std::vector<TrainPlacement>{{0x4001, 2, trackgraph::End::B},
                                                       {0x0018, 1, trackgraph::End::B},
                                                       {0x4002, 4, trackgraph::End::B}}));
    cs2config::LocomotiveFile one;
    one.locomotives.resize(1);
    one.locomotives[0].uid = 0x4005;
    EXPECT_EQ(spreadPlacements(one, demoGraph()).size(), 1U);
    EXPECT_TRUE(spreadPlacements({}, demoGraph()).empty());
}

} // namespace
} // namespace stellwerk::sim
