// The document's table of config file keys (chapter 7.1) and the names the files are stored under.

#include "cs2config/ConfigStreamKeys.h"

#include <gtest/gtest.h>

using namespace stellwerk::cs2config;

namespace {

struct Row {
    const char* key;
    const char* fileName;
    FollowUp followUp;
    StreamFormat format;
};

// Column by column as printed in 7.1 (file name, sender's follow-up info, stream data format).
const Row DocumentTable[] = {
    {"lokinfo", "lokinfo.cs2", FollowUp::LocoName, StreamFormat::Ms2Text},
    {"loknamen", "loknamen.cs2", FollowUp::Range, StreamFormat::Ms2Text},
    {"maginfo", "maginfo.cs2", FollowUp::Range, StreamFormat::Ms2Text},
    {"lokdb", "lokdb.bin", FollowUp::None, StreamFormat::Binary},
    {"lang", "lang.bin", FollowUp::None, StreamFormat::Binary},
    {"ldbver", "ldbver.cs2", FollowUp::None, StreamFormat::Ms2Text},
    {"langver", "langver.cs2", FollowUp::None, StreamFormat::Ms2Text},
    {"loks", "lokomotive.cs2", FollowUp::None, StreamFormat::Compressed},
    {"mags", "magnetartikel.cs2", FollowUp::None, StreamFormat::Compressed},
    {"gbs", "gleisbild.cs2", FollowUp::None, StreamFormat::Compressed},
    {"gbs-0", "gbs-0.cs2", FollowUp::None, StreamFormat::Compressed},
    {"fs", "fahrstrassen.cs2", FollowUp::None, StreamFormat::Compressed},
    {"loksstat", "lokomotive.sr2", FollowUp::None, StreamFormat::Compressed},
    {"magstat", "magnetartikel.sr2", FollowUp::None, StreamFormat::Compressed},
    {"gbsstat", "gleisbild.sr2", FollowUp::None, StreamFormat::Compressed},
    {"fsstat", "fahrstrassen.sr2", FollowUp::None, StreamFormat::Compressed},
};

} // namespace

TEST(ConfigStreamKeys, EveryKeyOfTheDocumentsTable) {
    for (const auto& row : DocumentTable) {
        SCOPED_TRACE(row.key);
        const auto found = findConfigFileKey(row.key);
        ASSERT_TRUE(found.has_value());
        EXPECT_EQ(found->followUp, row.followUp);
        EXPECT_EQ(found->format, row.format);
        EXPECT_EQ(fileNameForKey(row.key), row.fileName);
    }
}

TEST(ConfigStreamKeys, FollowUpFramesAsTheDocumentCountsThem) {
    EXPECT_EQ(findConfigFileKey("lokinfo")->followUpFrames(), 2); // "2 Pakete mit zusammen max. 16 Zeichen"
    EXPECT_EQ(findConfigFileKey("loknamen")->followUpFrames(), 1);
    EXPECT_EQ(findConfigFileKey("maginfo")->followUpFrames(), 1);
    EXPECT_EQ(findConfigFileKey("loks")->followUpFrames(), 0);
}

TEST(ConfigStreamKeys, FieldNotesAddLokstatAndLokliste) {
    EXPECT_EQ(fileNameForKey("lokstat"), "lokomotive.sr2");
    EXPECT_EQ(findConfigFileKey("lokliste")->format, StreamFormat::Ms2Text);
}

TEST(ConfigStreamKeys, TrackPlanPagesAreNumbered) {
    EXPECT_EQ(fileNameForKey("gbs-12"), "gbs-12.cs2");
    EXPECT_EQ(fileNameForKey("gbs-9999"), "gbs-9999.cs2");
    EXPECT_FALSE(findConfigFileKey("gbs-").has_value());
    EXPECT_FALSE(findConfigFileKey("gbs-#").has_value());
    EXPECT_FALSE(findConfigFileKey("gbs-1a").has_value());
    EXPECT_FALSE(findConfigFileKey("gbs-../x").has_value());
}

TEST(ConfigStreamKeys, UnknownKeysGiveNoFileName) {
    EXPECT_FALSE(findConfigFileKey("foo").has_value());
    EXPECT_EQ(fileNameForKey("foo"), "");
    EXPECT_EQ(fileNameForKey(""), "");
    EXPECT_EQ(fileNameForKey("../../x"), "");
}

TEST(ConfigStreamKeys, TableKeysAreUniqueAndFitInOneFrame) {
    const auto keys = configFileKeys();
    for (std::size_t i = 0; i < keys.size(); ++i) {
        EXPECT_LE(keys[i].key.size(), 8u) << keys[i].key;
        for (std::size_t j = i + 1; j < keys.size(); ++j)
            EXPECT_NE(keys[i].key, keys[j].key);
    }
}
