// lokomotive.sr2, the loco status file (stream keys lokstat/loksstat). The document does not
// describe it; the fixtures follow what mrsystem's lokstatus.c writes (see LocomotiveStateFile.h).
#include "cs2config/LocomotiveStateFile.h"

#include "ConfigTestSupport.h"

#include <gtest/gtest.h>
#include <string>

namespace stellwerk::cs2config::test {
namespace {

constexpr std::string_view statusFile = "[lokomotive]\n"
                                        "version\n"
                                        " .major=0\n"
                                        " .minor=1\n"
                                        "lokomotive\n"
                                        " .name=BR 86 173\n"
                                        " .velocity=250\n"
                                        " .richtung=1\n"
                                        " .funktionen\n"
                                        " ..nr=0\n"
                                        " ..wert=1\n"
                                        " .funktionen\n"
                                        " ..nr=1\n"
                                        "lokomotive\n"
                                        " .name=E 44\n"
                                        " .funktionen\n"
                                        " ..nr=0\n";

using ReadStatus = ReadModel<LocomotiveStateFile>;

ReadStatus readStatus(std::string_view text) {
    return readAs<LocomotiveStateFile>(text, "lokomotive.sr2");
}

TEST(LocomotiveStateFile, ReadsSpeedDirectionAndFunctionStates) {
    const ReadStatus read = readStatus(statusFile);
    EXPECT_TRUE(read.diagnostics.empty()) << read.diagnostics.formatAll();
    ASSERT_TRUE(read.file.version);
    EXPECT_EQ(read.file.version->major, 0);
    EXPECT_EQ(read.file.version->minor, 1);
    ASSERT_EQ(read.file.locomotives.size(), 2u);
    const LocomotiveState* br86 = read.file.find("BR 86 173");
    ASSERT_NE(br86, nullptr);
    EXPECT_EQ(br86->velocity, 250);
    EXPECT_EQ(br86->direction, TravelDirection::Backward);
    ASSERT_EQ(br86->functions.size(), 2u);
    EXPECT_EQ(br86->function(0)->value, 1);
    EXPECT_EQ(br86->function(1)->value, 0); // ..wert left out when off
    const LocomotiveState* e44 = read.file.find("E 44");
    ASSERT_NE(e44, nullptr);
    EXPECT_EQ(e44->velocity, 0); // left out when 0
    EXPECT_EQ(e44->direction, TravelDirection::Forward);
}

TEST(LocomotiveStateFile, WritesBackUnchangedAndChangesOnlyWhatChanged) {
    ReadStatus read = readStatus(statusFile);
    EXPECT_EQ(read.file.write().serialize(), statusFile);
    read.file.locomotives[0].velocity = 0;
    read.file.locomotives[1].functions[0].value = 1;
    std::string expected(statusFile);
    expected.replace(expected.find(" .velocity=250"), 14, " .velocity=0");
    expected += " ..wert=1\n";
    EXPECT_EQ(read.file.write().serialize(), expected);
}

TEST(LocomotiveStateFile, NewFileIsWrittenLikeMrsystemWritesIt) {
    LocomotiveStateFile file;
    file.version = LocomotiveStateFile::Version{};
    LocomotiveState state;
    state.name = "BR 86 173";
    state.velocity = 250;
    state.direction = TravelDirection::Backward;
    state.functions.push_back(FunctionState{0, 1, {}});
    state.functions.push_back(FunctionState{1, 0, {}});
    file.locomotives.push_back(state);
    state = LocomotiveState{};
    state.name = "E 44";
    state.functions.push_back(FunctionState{0, 0, {}});
    file.locomotives.push_back(state);
    EXPECT_EQ(file.write().serialize(), statusFile);
}

TEST(LocomotiveStateFile, AcceptsTheLokstatusHeaderAndWarnsAboutOthers) {
    std::string text(statusFile);
    text.replace(1, 10, "lokstatus");
    EXPECT_TRUE(readStatus(text).diagnostics.empty());
    text.replace(1, 9, "gleisbild");
    const ReadStatus read = readStatus(text);
    ASSERT_EQ(read.diagnostics.items().size(), 1u);
    EXPECT_EQ(read.diagnostics.items()[0].message, "section '[gleisbild]' is not '[lokomotive]'");
    EXPECT_EQ(read.file.locomotives.size(), 2u);
}

TEST(LocomotiveStateFile, ReportsRecordsThatCannotBeMatchedAndDuplicates) {
    std::string text(statusFile);
    text += "lokomotive\n .velocity=3\nlokomotive\n .name=E 44\n .richtung=4294967295\n .spin=1\n";
    const ReadStatus read = readStatus(text);
    const auto& items = read.diagnostics.items();
    ASSERT_EQ(items.size(), 4u) << read.diagnostics.formatAll();
    EXPECT_EQ(items[0].line, 20);
    EXPECT_EQ(items[0].message, "two status records for 'E 44' (lines 14 and 20)");
    EXPECT_EQ(items[1].message, "locomotive status record without a name");
    EXPECT_EQ(items[1].line, 18);
    EXPECT_EQ(items[2].message, "unknown key '.spin' in a locomotive status record");
    EXPECT_EQ(items[2].line, 23);
    EXPECT_EQ(items[3].message, "direction '.richtung=4294967295' is neither 0 (forward) nor 1 (backward)");
    EXPECT_EQ(read.file.locomotives[3].direction, TravelDirection::Unknown);
    EXPECT_EQ(read.file.write().serialize(), text);
}

TEST(LocomotiveStateFile, JsonListsTheStates) {
    const ReadStatus read = readStatus(statusFile);
    const std::string json = toJson(read.file);
    EXPECT_NE(json.find("\"kind\": \"lokomotive.sr2\""), std::string::npos);
    EXPECT_NE(json.find("\"name\": \"BR 86 173\""), std::string::npos);
    EXPECT_NE(json.find("\"velocity\": 250"), std::string::npos);
    EXPECT_NE(json.find("\"direction\": \"backward\""), std::string::npos);
}

} // namespace
} // namespace stellwerk::cs2config::test
