// The station's files: in memory, from a folder, from the embedded demo; keys and paths.

#include "SimTestSupport.h"
#include "cs2config/LocomotivePicture.h"

#include <QTemporaryDir>
#include <fstream>

namespace stellwerk::sim::test {
namespace {

TEST(StationLayout, KeysMapToTheirFiles) {
    const StationLayout layout = inlineLayout();
    EXPECT_EQ(layout.pathForKey("loks"), "lokomotive.cs2");
    EXPECT_EQ(layout.pathForKey("mags"), "magnetartikel.cs2");
    EXPECT_EQ(layout.pathForKey("fs"), "fahrstrassen.cs2");
    EXPECT_EQ(layout.pathForKey("gbs"), "gleisbild.cs2");
    EXPECT_EQ(layout.pathForKey("gbs-0"), "gleisbilder/Bahnhof.cs2");
    EXPECT_EQ(layout.pathForKey("gbs-1"), std::nullopt) << "listed page without a file";
    EXPECT_EQ(layout.pathForKey("gbs-x"), std::nullopt);
    EXPECT_EQ(layout.fileForPath("gleisbilder/Bahnhof.cs2"), std::string(stationPage));
}

TEST(StationLayout, TypedModelsAndPagesById) {
    const StationLayout layout = inlineLayout();
    EXPECT_EQ(layout.locomotives().locomotives.size(), 4u);
    EXPECT_EQ(layout.accessories().accessories.size(), 2u);
    ASSERT_NE(layout.page(0), nullptr);
    EXPECT_EQ(layout.page(0)->name, "Bahnhof");
    EXPECT_EQ(layout.page(0)->page.elements.size(), 2u);
    EXPECT_FALSE(layout.page(1)->loaded);
}

TEST(StationLayout, MissingFilesAreReported) {
    const StationLayout layout = inlineLayout();
    bool routesReported = false;
    for (const std::string& line : layout.diagnostics())
        routesReported = routesReported || line.find("fahrstrassen.cs2") != std::string::npos;
    EXPECT_TRUE(routesReported);
}

TEST(StationLayout, LoadReadsAFolder) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const std::filesystem::path root = dir.path().toStdString();
    std::filesystem::create_directories(root / "gleisbilder");
    std::ofstream(root / "lokomotive.cs2") << locomotives;
    std::ofstream(root / "gleisbild.cs2") << trackPlan;
    std::ofstream(root / "gleisbilder" / "Bahnhof.cs2") << stationPage;
    cs2config::Diagnostics diagnostics;
    const StationLayout layout = StationLayout::load(root, diagnostics);
    EXPECT_EQ(layout.fileForKey("loks"), std::string(locomotives));
    EXPECT_EQ(layout.fileForKey("gbs-0"), std::string(stationPage));
    EXPECT_EQ(layout.locomotives().locomotives.size(), 4u);
}

TEST(StationLayout, LoadTakesThePicturesOfTheIconsFolderBesideTheConfig) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const std::filesystem::path root = dir.path().toStdString();
    std::filesystem::create_directories(root / "config");
    std::filesystem::create_directories(root / "icons");
    std::ofstream(root / "config" / "lokomotive.cs2") << locomotives;
    std::ofstream(root / "icons" / "BR 86.png") << "picture bytes";
    std::ofstream(root / "icons" / "notes.txt") << "not a picture";
    std::ofstream(root / "icons" / "huge.png") << std::string(cs2config::picture::MaxBytes + 1, 'x');
    cs2config::Diagnostics diagnostics;
    const StationLayout layout = StationLayout::load(root / "config" / "", diagnostics);
    EXPECT_EQ(layout.pictureFor("BR 86.png"), "picture bytes");
    EXPECT_EQ(layout.pictures().size(), 1u);
    EXPECT_NE(diagnostics.formatAll().find("huge.png is larger than a locomotive picture may be"),
              std::string::npos)
        << diagnostics.formatAll();
}

TEST(StationLayout, DemoIsServedOrItsAbsenceSaidClearly) {
    const StationLayout layout = StationLayout::demo();
    if (layout.files().empty()) {
        ASSERT_FALSE(layout.diagnostics().empty());
        EXPECT_NE(layout.diagnostics().front().find(":/demo-layout/config/"), std::string::npos);
        EXPECT_NE(layout.diagnostics().front().find("missing"), std::string::npos);
    } else {
        EXPECT_TRUE(layout.fileForKey("loks").has_value());
        EXPECT_FALSE(layout.locomotives().locomotives.empty());
    }
}

} // namespace
} // namespace stellwerk::sim::test
