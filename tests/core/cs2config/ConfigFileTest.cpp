// ConfigFile: a file of the CS2 family recognised, read into its typed model and written back.

#include "cs2config/ConfigFile.h"

#include "ConfigTestSupport.h"

#include <unistd.h>

namespace stellwerk::cs2config::test {
namespace {

ConfigFile fromText(std::string_view text, const std::string& name = "test.cs2") {
    return ConfigFile::fromBytes(text, name);
}

TEST(ConfigFile, CorpusFilesAreRecognisedAndSummarised) {
    const struct {
        std::string_view file;
        ConfigKind kind;
        std::string summary;
    } cases[] = {
        {corpus::lokomotiveTrainControl, ConfigKind::Locomotives,
         "locomotives (lokomotive.cs2): 108 locomotives, 1712 functions"},
        {corpus::lokomotiveSrseii, ConfigKind::Locomotives,
         "locomotives (lokomotive.cs2): 9 locomotives, 160 functions"},
        {corpus::magnetartikelTrainControl, ConfigKind::Accessories,
         "accessories (magnetartikel.cs2): 127 accessories"},
        {corpus::fahrstrassen, ConfigKind::Routes, "routes (fahrstrassen.cs2): 81 routes, 689 items"},
        {corpus::gleisbildMrFlexi, ConfigKind::TrackPlan, "track plan index (gleisbild.cs2): 11 pages"},
        {corpus::karben, ConfigKind::TrackPage, "track plan page: 37 elements"},
        {corpus::gbs0, ConfigKind::TrackPage, "track plan page: 144 elements"},
        {corpus::testPage, ConfigKind::TrackPage, "track plan page: 101 elements"},
    };
    for (const auto& expected : cases) {
        const ConfigFile file = ConfigFile::load(corpusPath(expected.file));
        EXPECT_EQ(file.kind(), expected.kind) << expected.file;
        EXPECT_EQ(file.summary(), expected.summary) << expected.file;
        EXPECT_TRUE(file.usable()) << expected.file;
    }
}

TEST(ConfigFile, EveryCorpusFileWritesBackThroughItsModelByteForByte) {
    for (std::string_view name :
         {corpus::gleisbildGbert, corpus::karben, corpus::gbs0, corpus::gleisbildMrFlexi,
          corpus::gleisbildSample, corpus::testPage, corpus::lokomotiveTrainControl, corpus::lokomotiveGbert,
          corpus::lokomotiveSrseii, corpus::lokomotiveCorrupted, corpus::magnetartikelTrainControl,
          corpus::magnetartikelGbert, corpus::fahrstrassen, corpus::cs3TrackPlan, corpus::cs3Loco}) {
        const ConfigFile file = ConfigFile::load(corpusPath(name));
        EXPECT_EQ(file.write(), readCorpus(name)) << name;
    }
}

TEST(ConfigFile, Ms2StreamsOfTheDocumentAreRecognised) {
    // 8.4 (shortened), 8.5, 8.6 and 8.8.
    const ConfigFile lokinfo =
        fromText("[lokomotive]\nlok\n  .uid=0x4005\n  .name=M4\n  .adresse=0x9\n  .typ=mfx\n"
                 "  .fkt\n  ..nr=0\n  ..typ=32\n  .fkt\n  ..nr=1\n  ..typ=12\n",
                 "lokinfo");
    EXPECT_EQ(lokinfo.kind(), ConfigKind::LocoInfo);
    EXPECT_EQ(lokinfo.summary(), "MS2 lokinfo stream: 'M4', 2 functions");

    const ConfigFile loknamen = fromText("[lokomotive]\nlok\n  .nr=3\n  .name=MaK 1206 ACTS\nlok\n  .nr=4\n"
                                         "  .name=M4-RIOs\nnumloks\n  .wert=8\n",
                                         "loknamen");
    EXPECT_EQ(loknamen.kind(), ConfigKind::LocoNames);
    EXPECT_EQ(loknamen.summary(), "MS2 loknamen stream: 2 names of 8 locomotives");

    const ConfigFile maginfo =
        fromText("[magnetartikel]\nartikel\n  .id=3\n  .name=1.3\n  .typ=rechtsweiche\n"
                 "  .schaltzeit=200\n  .dectyp=mm2\n",
                 "maginfo");
    EXPECT_EQ(maginfo.kind(), ConfigKind::Accessories);
    EXPECT_EQ(maginfo.summary(), "accessories (magnetartikel.cs2): 1 accessory");

    const ConfigFile ldbver = fromText(".version=9  \n.monat=2  \n.jahr=10  \n.anzahl=1078", "ldbver");
    EXPECT_EQ(ldbver.kind(), ConfigKind::LocoDbVersion);
    EXPECT_EQ(ldbver.summary(), "MS2 ldbver stream: version 9 of 2/10, 1078 entries");
    EXPECT_TRUE(ldbver.usable());
}

TEST(ConfigFile, StatusFilesAreToldApartByTheirName) {
    EXPECT_EQ(fromText("[lokomotive]\nlokomotive\n .name=V 100\n .velocity=300\n", "lokomotive.sr2").kind(),
              ConfigKind::LocomotiveStatus);
    EXPECT_EQ(fromText("[magnetartikel]\nartikel\n .id=1\n .stellung=1\n", "magnetartikel.sr2").kind(),
              ConfigKind::AccessoryStatus);
    EXPECT_EQ(fromText("[gleisbild]\nelement\n .id=0x102\n .zustand=1\n", "gleisbild.sr2").kind(),
              ConfigKind::TrackStatus);
    EXPECT_EQ(fromText("[lokomotive]\nlokomotive\n .name=V 100\n", "lokomotive.cs2").kind(),
              ConfigKind::Locomotives);
}

TEST(ConfigFile, UnknownSectionIsReadAsAPlainDocument) {
    const ConfigFile file = fromText("[geraet]\ngeraet\n .name=Gleisbox\n", "geraet.vrs");
    EXPECT_EQ(file.kind(), ConfigKind::Unknown);
    EXPECT_TRUE(file.usable());
    ASSERT_EQ(file.diagnostics().items().size(), 1u);
    EXPECT_EQ(file.diagnostics().items()[0].message, "unknown section [geraet]");
    EXPECT_EQ(file.write(), "[geraet]\ngeraet\n .name=Gleisbox\n");
    EXPECT_EQ(
        file.json(),
        "{\n  \"section\": \"geraet\",\n  \"entries\": [\n    {\n      \"key\": \"geraet\",\n"
        "      \"line\": 2,\n      \"entries\": [\n        {\n          \"key\": \"name\",\n"
        "          \"line\": 3,\n          \"value\": \"Gleisbox\"\n        }\n      ]\n    }\n  ]\n}\n");
}

TEST(ConfigFile, AFileWithADamagedHeaderIsReadAsWhatItsNameSays) {
    const struct {
        std::string name;
        std::string text;
        ConfigKind kind;
        std::string summary;
    } cases[] = {
        {"magnetartikel.cs2", "[magnetart\nartikel\n .id=1\n .typ=rechtsweiche\n", ConfigKind::Accessories,
         "1 accessory"},
        {"lokomotive.cs2", " komotive]\nlokomotive\n .name=V 100\n .uid=0x5\n", ConfigKind::Locomotives,
         "1 locomotive"},
        {"fahrstrassen.cs2", "[fahr\xFF\nfahrstrasse\n .id=1\n .name=Einfahrt\n", ConfigKind::Routes,
         "1 route"},
        {"config/gleisbild.cs2", "gleisbild]\nseite\n .id=1\n .name=Bahnhof\n", ConfigKind::TrackPlan,
         "1 page"},
        {"config/gleisbilder/Bahnhof.cs2", "[gleisbildseit\nelement\n .id=0x102\n .typ=gerade\n",
         ConfigKind::TrackPage, "1 element"},
    };
    for (const auto& test : cases) {
        const ConfigFile file = fromText(test.text, test.name);
        EXPECT_EQ(file.kind(), test.kind) << test.name;
        EXPECT_TRUE(file.usable()) << test.name << "\n" << file.diagnostics().formatAll();
        EXPECT_NE(file.summary().find(test.summary), std::string::npos) << file.summary();
        EXPECT_NE(file.diagnostics().formatAll().find(
                      test.name + ": warning: no readable section header; read as " +
                      std::string(kindName(test.kind)) + " because of the file name"),
                  std::string::npos)
            << file.diagnostics().formatAll();
        EXPECT_EQ(file.write(), test.text) << test.name;
    }
}

TEST(ConfigFile, AReadableHeaderWinsOverTheName) {
    const ConfigFile file = fromText("[magnetartikel]\nartikel\n .id=1\n", "lokomotive.cs2");
    EXPECT_EQ(file.kind(), ConfigKind::Accessories);
}

TEST(ConfigFile, AHeaderWithJunkInFrontIsReadAsItsSection) {
    const ConfigFile file =
        fromText("Bau [magnetartikel]\nartikel\n .id=1\n .typ=rechtsweiche\n", "mags.cs2");
    EXPECT_EQ(file.kind(), ConfigKind::Accessories);
    EXPECT_EQ(file.summary(), "accessories (magnetartikel.cs2): 1 accessory");
    EXPECT_EQ(file.write(), "Bau [magnetartikel]\nartikel\n .id=1\n .typ=rechtsweiche\n");
}

TEST(ConfigFile, FileNamesThatSayWhatAFileIs) {
    EXPECT_EQ(configKindByName("lokomotive.cs2"), ConfigKind::Locomotives);
    EXPECT_EQ(configKindByName("/x/config/magnetartikel.sr2"), ConfigKind::AccessoryStatus);
    EXPECT_EQ(configKindByName("gleisbild.sr2"), ConfigKind::TrackStatus);
    EXPECT_EQ(configKindByName("gleisbilder/5 - Test.cs2"), ConfigKind::TrackPage);
    EXPECT_EQ(configKindByName("gbs-3.cs2"), ConfigKind::TrackPage);
    EXPECT_EQ(configKindByName("notes.cs2"), std::nullopt);
    EXPECT_EQ(configKindByName("gleisbilder/readme.txt"), std::nullopt);
    // Without a readable header and without a telling name the file stays a plain document.
    EXPECT_EQ(fromText("[geraet\ngeraet\n .name=Gleisbox\n", "geraet.vrs").kind(), ConfigKind::Unknown);
}

TEST(ConfigFile, WhatIsNotACs2FileIsNotUsable) {
    EXPECT_EQ(fromText("Dear station,\nplease\n").kind(), ConfigKind::NotConfiguration);
    EXPECT_EQ(fromText(std::string_view("\x89PNG\r\n\x1A\n\0\0", 10)).kind(), ConfigKind::NotConfiguration);
    EXPECT_FALSE(fromText("").usable());
}

TEST(ConfigFile, Cs3TrackPlanIsReportedAsNotUsable) {
    const ConfigFile file = ConfigFile::load(corpusPath(corpus::cs3TrackPlan));
    EXPECT_EQ(file.kind(), ConfigKind::TrackPage);
    EXPECT_FALSE(file.usable());
    EXPECT_TRUE(file.diagnostics().hasErrors());
}

TEST(ConfigFile, MissingAndOversizedFilesAreRefusedWithAReason) {
    const ConfigFile missing = ConfigFile::load("/nonexistent/lokomotive.cs2");
    EXPECT_FALSE(missing.usable());
    ASSERT_EQ(missing.diagnostics().items().size(), 1u);
    EXPECT_EQ(missing.diagnostics().items()[0].message.rfind("cannot read the file", 0), 0u);

    const std::filesystem::path huge =
        std::filesystem::temp_directory_path() / ("stellwerk-huge-" + std::to_string(::getpid()) + ".cs2");
    { std::ofstream(huge) << "[lokomotive]\n"; }
    std::filesystem::resize_file(huge, ConfigFile::maxFileSize + 1); // sparse: costs no disk
    const ConfigFile oversized = ConfigFile::load(huge);
    std::filesystem::remove(huge);
    EXPECT_FALSE(oversized.usable());
    ASSERT_EQ(oversized.diagnostics().items().size(), 1u);
    EXPECT_NE(oversized.diagnostics().items()[0].message.find("more than the"), std::string::npos);
}

TEST(ConfigFile, JsonOfLocomotivesCarriesTheirFunctions) {
    const ConfigFile file = ConfigFile::load(corpusPath(corpus::lokomotiveSrseii));
    const std::string json = file.json();
    EXPECT_NE(json.find("\"functions\""), std::string::npos);
    EXPECT_NE(json.find("\"name\": \"260 417-1 DB\""), std::string::npos);
    EXPECT_NE(json.find("\"number\": 31"), std::string::npos) << "F16-F31 from .funktionen_2";
}

} // namespace
} // namespace stellwerk::cs2config::test
