// The MS2 text streams of the document's chapters 8.4 (lokinfo), 8.5 (loknamen; lokliste has the
// same form) and 8.8 (ldbver), read and written from the document's own examples.
#include "ConfigTestSupport.h"
#include "cs2config/LocomotiveFile.h"
#include "cs2config/Ms2LocoDatabaseVersion.h"
#include "cs2config/Ms2LocoInfo.h"
#include "cs2config/Ms2LocoNames.h"

#include <array>
#include <gtest/gtest.h>
#include <string>

namespace stellwerk::cs2config::test {
namespace {

// 8.4 as printed (the .mfxAdr lines are split off into a second box in the document).
constexpr std::string_view lokinfoExample = "[lokomotive]\n"
                                            "lok\n"
                                            "  .uid=0x4005\n"
                                            "  .name=M4\n"
                                            "  .adresse=0x9\n"
                                            "  .typ=mfx\n"
                                            "  .mfxuid=0xff001234\n"
                                            "  .av=64\n"
                                            "  .bv=48\n"
                                            "  .volume=64\n"
                                            "  .vmax=255\n"
                                            "  .vmin=12\n"
                                            "  .fkt\n  ..nr=0\n  ..typ=32\n"
                                            "  .fkt\n  ..nr=1\n  ..typ=12\n"
                                            "  .fkt\n  ..nr=2\n  ..typ=38\n"
                                            "  .fkt\n  ..nr=3\n  ..typ=43\n"
                                            "  .fkt\n  ..nr=4\n  ..typ=91\n"
                                            "  .fkt\n  ..nr=5\n  ..typ=22\n"
                                            "  .fkt\n  ..nr=6\n  ..typ=39\n"
                                            "  .fkt\n  ..nr=7\n  ..typ=31\n"
                                            "  .fkt\n  ..nr=8\n  ..typ=19\n"
                                            "  .fkt\n  ..nr=9\n  ..typ=133\n"
                                            "  .fkt\n  ..nr=10\n  ..typ=27\n"
                                            "  .fkt\n  ..nr=11\n  ..typ=29\n"
                                            "  .fkt\n  ..nr=12\n  ..typ=89\n"
                                            "  .fkt\n  ..nr=13\n  ..typ=16\n"
                                            "  .fkt\n  ..nr=14\n  ..typ=14\n"
                                            "  .fkt\n  ..nr=15\n  ..typ=4\n"
                                            "  .mfxAdr\n"
                                            "  ..target=2\n"
                                            "  ..name=3\n"
                                            "  ..addr=136\n"
                                            "  ..xcel=78\n"
                                            "  ..speedtable=79\n"
                                            "  ..volume=117\n"
                                            "  ..numfunc=16\n"
                                            "  ..func=21\n";

constexpr std::array<int, 16> lokinfoIcons{32, 12, 38, 43, 91, 22, 39, 31, 19, 133, 27, 29, 89, 16, 14, 4};

// 8.5 as printed.
constexpr std::string_view loknamenExample = "[lokomotive]\n"
                                             "lok\n"
                                             "  .nr=3\n"
                                             "  .name=MaK 1206 ACTS\n"
                                             "lok\n"
                                             "  .nr=4\n"
                                             "  .name=M4-RIOs\n"
                                             "numloks\n"
                                             "  .wert=8\n";

// 8.8 as printed: no header, no record, trailing spaces.
constexpr std::string_view ldbverExample = ".version=9  \n.monat=2  \n.jahr=10  \n.anzahl=1078";

template <class Model>
Model readModel(std::string_view text, Diagnostics& diagnostics) {
    return Model::read(Document::parse(text, diagnostics), diagnostics);
}

TEST(Ms2LocoInfo, DocumentExampleReadsTheLocomotive) {
    Diagnostics diagnostics;
    const Ms2LocoInfo info = readModel<Ms2LocoInfo>(lokinfoExample, diagnostics);
    EXPECT_TRUE(diagnostics.empty()) << diagnostics.formatAll();
    ASSERT_TRUE(info.locomotive);
    const Locomotive& locomotive = *info.locomotive;
    EXPECT_EQ(locomotive.uid, 0x4005u);
    EXPECT_EQ(locomotive.name, "M4");
    EXPECT_EQ(locomotive.address, 9u);
    EXPECT_EQ(locomotive.decoder, LocomotiveDecoder::Mfx);
    EXPECT_EQ(locomotive.mfxUid, 0xff001234u);
    EXPECT_EQ(locomotive.acceleration, 64);
    EXPECT_EQ(locomotive.braking, 48);
    EXPECT_EQ(locomotive.volume, 64);
    EXPECT_EQ(locomotive.vMax, 255);
    EXPECT_EQ(locomotive.vMin, 12);
    ASSERT_EQ(locomotive.functions.size(), 16u);
    for (std::size_t i = 0; i < lokinfoIcons.size(); ++i) {
        EXPECT_EQ(locomotive.functions[i].number, static_cast<int>(i));
        EXPECT_EQ(locomotive.functions[i].icon, lokinfoIcons[i]);
    }
}

// "Als einzigen Zusatz enthält lokinfo für mfx-Loks in der Untersektion .mfxAdr ..."
TEST(Ms2LocoInfo, DocumentExampleReadsTheMfxAddress) {
    Diagnostics diagnostics;
    const Ms2LocoInfo info = readModel<Ms2LocoInfo>(lokinfoExample, diagnostics);
    ASSERT_TRUE(info.locomotive && info.locomotive->mfxAddress);
    const MfxAddress& mfx = *info.locomotive->mfxAddress;
    EXPECT_EQ(mfx.target, 2);
    EXPECT_EQ(mfx.name, 3);
    EXPECT_EQ(mfx.address, 136);
    EXPECT_EQ(mfx.acceleration, 78);
    EXPECT_EQ(mfx.speedTable, 79);
    EXPECT_EQ(mfx.volume, 117);
    EXPECT_EQ(mfx.functionCount, 16);
    EXPECT_EQ(mfx.functions, 21);
}

TEST(Ms2LocoInfo, DocumentExampleWritesBackUnchanged) {
    Diagnostics diagnostics;
    const Ms2LocoInfo info = readModel<Ms2LocoInfo>(lokinfoExample, diagnostics);
    EXPECT_EQ(info.write().serialize(), lokinfoExample);
}

// What a station sends for a locomotive of its lokomotive.cs2: the document's example, exactly.
TEST(Ms2LocoInfo, WrittenFromALocomotiveGivesTheDocumentExample) {
    Locomotive locomotive;
    locomotive.uid = 0x4005;
    locomotive.name = "M4";
    locomotive.address = 9;
    locomotive.decoder = LocomotiveDecoder::Mfx;
    locomotive.mfxUid = 0xff001234;
    locomotive.acceleration = 64;
    locomotive.braking = 48;
    locomotive.volume = 64;
    locomotive.vMax = 255;
    locomotive.vMin = 12;
    locomotive.symbol = 2;     // not part of lokinfo
    locomotive.tachoMax = 200; // not part of lokinfo
    locomotive.source = Node::entry(0, "lokomotive", std::nullopt, {});
    for (std::size_t i = 0; i < lokinfoIcons.size(); ++i)
        locomotive.functions.push_back(Function{static_cast<int>(i), lokinfoIcons[i], 0, 0, {}});
    locomotive.mfxAddress = MfxAddress{2, 3, 136, 78, 79, 117, 16, 21, {}};
    locomotive.traction.push_back(TractionMember{0x4006, "B", {}});
    EXPECT_EQ(Ms2LocoInfo::from(locomotive).write().serialize(), lokinfoExample);
}

TEST(Ms2LocoInfo, MissingLokRecordIsAnError) {
    Diagnostics diagnostics;
    const Ms2LocoInfo info = readModel<Ms2LocoInfo>("[lokomotive]\nlokomotive\n .name=x\n", diagnostics);
    EXPECT_FALSE(info.locomotive);
    ASSERT_EQ(diagnostics.items().size(), 2u) << diagnostics.formatAll();
    EXPECT_EQ(diagnostics.items()[0].message, "lokinfo without a 'lok' record");
    EXPECT_EQ(diagnostics.items()[0].severity, Diagnostic::Severity::Error);
    EXPECT_EQ(diagnostics.items()[1].message, "unknown record 'lokomotive'");
}

TEST(Ms2LocoInfo, JsonShowsTheLocomotive) {
    Diagnostics diagnostics;
    const std::string json = toJson(readModel<Ms2LocoInfo>(lokinfoExample, diagnostics));
    EXPECT_NE(json.find("\"kind\": \"lokinfo\""), std::string::npos);
    EXPECT_NE(json.find("\"uid\": \"0x4005\""), std::string::npos);
    EXPECT_NE(json.find("\"speedTable\": 79"), std::string::npos);
}

TEST(Ms2LocoNames, DocumentExampleReadsTheEntriesAndTheTotal) {
    Diagnostics diagnostics;
    const Ms2LocoNames names = readModel<Ms2LocoNames>(loknamenExample, diagnostics);
    EXPECT_TRUE(diagnostics.empty()) << diagnostics.formatAll();
    ASSERT_EQ(names.entries.size(), 2u);
    EXPECT_EQ(names.entries[0].number, 3);
    EXPECT_EQ(names.entries[0].name, "MaK 1206 ACTS");
    EXPECT_EQ(names.entries[1].number, 4);
    EXPECT_EQ(names.entries[1].name, "M4-RIOs");
    EXPECT_EQ(names.total, 8);
    EXPECT_EQ(names.write().serialize(), loknamenExample);
}

TEST(Ms2LocoNames, NewStreamIsWrittenAsInTheDocument) {
    Ms2LocoNames names;
    names.entries.push_back(Ms2LocoName{3, "MaK 1206 ACTS", {}});
    names.entries.push_back(Ms2LocoName{4, "M4-RIOs", {}});
    names.total = 8;
    EXPECT_EQ(names.write().serialize(), loknamenExample);
}

TEST(Ms2LocoNames, EntriesBeyondTheTotalAndTwiceTheSameNumberAreReported) {
    Diagnostics diagnostics;
    const Ms2LocoNames names =
        readModel<Ms2LocoNames>("[lokomotive]\nlok\n  .nr=3\n  .name=A\nlok\n  .nr=3\n  .name=B\nlok\n  "
                                ".nr=8\n  .name=C\nnumloks\n  .wert=8\n",
                                diagnostics);
    const auto& items = diagnostics.items();
    ASSERT_EQ(items.size(), 2u) << diagnostics.formatAll();
    EXPECT_EQ(items[0].message, "two entries with '.nr=3' (lines 2 and 5)");
    EXPECT_EQ(items[1].message, "entry '.nr=8' is outside the 8 locomotives of 'numloks'");
    EXPECT_EQ(items[1].line, 8);
    EXPECT_EQ(names.entries.size(), 3u);
}

TEST(Ms2LocoNames, JsonListsTheEntries) {
    Diagnostics diagnostics;
    const std::string json = toJson(readModel<Ms2LocoNames>(loknamenExample, diagnostics));
    EXPECT_NE(json.find("\"total\": 8"), std::string::npos);
    EXPECT_NE(json.find("\"name\": \"M4-RIOs\""), std::string::npos);
}

TEST(Ms2LocoDatabaseVersion, DocumentExampleReadsAllFourValues) {
    Diagnostics diagnostics;
    const Ms2LocoDatabaseVersion version = readModel<Ms2LocoDatabaseVersion>(ldbverExample, diagnostics);
    ASSERT_EQ(diagnostics.items().size(), 1u) << diagnostics.formatAll();
    EXPECT_EQ(diagnostics.items()[0].message, "no [section] header"); // expected for this stream
    EXPECT_EQ(version.version, 9);
    EXPECT_EQ(version.month, 2);
    EXPECT_EQ(version.year, 10);
    EXPECT_EQ(version.count, 1078);
}

TEST(Ms2LocoDatabaseVersion, KeepsTheTrailingSpacesOfUnchangedLines) {
    Diagnostics diagnostics;
    Ms2LocoDatabaseVersion version = readModel<Ms2LocoDatabaseVersion>(ldbverExample, diagnostics);
    EXPECT_EQ(version.write().serialize(), ldbverExample);
    version.count = 1079;
    version.month = 3;
    EXPECT_EQ(version.write().serialize(), ".version=9  \n.monat=3\n.jahr=10  \n.anzahl=1079");
}

TEST(Ms2LocoDatabaseVersion, NewStreamHasTheFourLines) {
    Ms2LocoDatabaseVersion version;
    version.version = 9;
    version.month = 2;
    version.year = 10;
    version.count = 1078;
    EXPECT_EQ(version.write().serialize(), ".version=9\n.monat=2\n.jahr=10\n.anzahl=1078\n");
}

TEST(Ms2LocoDatabaseVersion, MissingAndOddValuesAreReported) {
    Diagnostics diagnostics;
    const Ms2LocoDatabaseVersion version =
        readModel<Ms2LocoDatabaseVersion>(".version=9\n.monat=13\n.jahr=ten\n", diagnostics);
    const auto& items = diagnostics.items();
    ASSERT_EQ(items.size(), 4u) << diagnostics.formatAll();
    EXPECT_EQ(items[1].message, "'.jahr' is not a number: 'ten'");
    EXPECT_EQ(items[2].message, "month 13 is not 1-12");
    EXPECT_EQ(items[3].message, "ldbver without '.anzahl'");
    EXPECT_EQ(version.year, 0);
}

TEST(Ms2LocoDatabaseVersion, JsonHasTheFourValues) {
    Diagnostics diagnostics;
    EXPECT_EQ(toJson(readModel<Ms2LocoDatabaseVersion>(ldbverExample, diagnostics)),
              "{\n  \"kind\": \"ldbver\",\n  \"version\": 9,\n  \"month\": 2,\n  \"year\": 10,\n  \"count\": "
              "1078\n}\n");
}

} // namespace
} // namespace stellwerk::cs2config::test
