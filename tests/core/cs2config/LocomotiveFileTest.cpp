// lokomotive.cs2 as real stations write it: TrainControl's corpus file (108 locos, mfx/mm2/dcc, a traction
// unit, no final newline) and edits of the structure that must change only what they change.

#include "cs2config/LocomotiveFile.h"

#include "ConfigTestSupport.h"
#include "LocomotiveFileTestSupport.h"
#include "cs2config/LocomotiveValues.h"

#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace stellwerk::cs2config::test {
namespace {

using namespace locofile;

// --- TrainControl's file: 108 locos, mfx/mm2/dcc, traction, no final newline -------------------

TEST(LocomotiveFileTrainControl, ReadsEveryLocomotiveAndFunction) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveTrainControl);
    const LocomotiveFile& file = read.file;
    EXPECT_EQ(file.locomotives.size(), 108u);
    EXPECT_EQ(file.functionCount(), 1712u); // 107 locos x F0-F15; "ABnsNoFunc" has none
    EXPECT_EQ(countDecoder(file, LocomotiveDecoder::Mfx), 74u);
    EXPECT_EQ(countDecoder(file, LocomotiveDecoder::Mm2Dil8), 24u);
    EXPECT_EQ(countDecoder(file, LocomotiveDecoder::Mm2Prg), 8u);
    EXPECT_EQ(countDecoder(file, LocomotiveDecoder::Dcc), 2u);
    EXPECT_EQ(countFunctions(file, [](const Function& f) { return f.value == 1; }), 50u);
    EXPECT_EQ(countFunctions(file, [](const Function& f) { return f.trigger() == FunctionTrigger::Timed; }),
              54u);
    EXPECT_FALSE(file.cs3Native);
    ASSERT_TRUE(file.version);
    EXPECT_EQ(file.version->major, 0); // the file leaves .major out
    EXPECT_EQ(file.version->minor, 3);
    EXPECT_EQ(file.session, 35361);
}

TEST(LocomotiveFileTrainControl, ReadsTheFieldsOfTheFirstLocomotive) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveTrainControl);
    const Locomotive& first = read.file.locomotives.front();
    EXPECT_EQ(first.source.lineNumber(), 6);
    EXPECT_EQ(first.name, "BR 85 006 Gl.");
    EXPECT_EQ(first.direction, TravelDirection::Backward);
    EXPECT_EQ(first.uid, 0x5u);
    EXPECT_EQ(first.address, 5u);
    EXPECT_EQ(first.decoder, LocomotiveDecoder::Mm2Dil8);
    EXPECT_EQ(first.icon, "BR 85");
    EXPECT_EQ(first.symbol, 2);
    EXPECT_EQ(first.acceleration, 20);
    EXPECT_EQ(first.braking, 0); // missing: 0
    EXPECT_EQ(first.programmingMask, 0x40);
    EXPECT_EQ(first.tachoMax, 80);
    EXPECT_EQ(first.extendedProtocol, 32767);
    EXPECT_EQ(first.inTraction, Locomotive::noTraction);
    ASSERT_EQ(first.functions.size(), 16u);
    EXPECT_EQ(first.functions[0].icon, 1);
    EXPECT_EQ(first.functions[1].icon, 7);
    EXPECT_EQ(first.functions[2].icon, 0); // "functions with only ..nr"
    EXPECT_EQ(first.functions[4].icon, 18);
    EXPECT_EQ(first.functions[15].number, 15);
}

TEST(LocomotiveFileTrainControl, ReadsTheTractionUnitAndItsMembers) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveTrainControl);
    const Locomotive* unit = read.file.find(0x2c01);
    ASSERT_NE(unit, nullptr);
    EXPECT_EQ(unit->name, "OBB 1043");
    EXPECT_EQ(unit->address, 0x98f4u);
    ASSERT_EQ(unit->traction.size(), 2u);
    EXPECT_EQ(unit->traction[0].uid, 0x400bu);
    EXPECT_EQ(unit->traction[0].name, "1043 006-4 ÖBB");
    EXPECT_EQ(unit->traction[1].uid, 0x400au);
    EXPECT_EQ(unit->traction[1].name, "1043 001-5 ÖBB");
    EXPECT_EQ(read.file.find(0x400a)->inTraction, 0x2c01u);
    EXPECT_EQ(read.file.find(0x400b)->inTraction, 0x2c01u);
}

TEST(LocomotiveFileTrainControl, ReadsNamesWithEqualsSignsAndUmlauts) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveTrainControl);
    EXPECT_NE(read.file.find(0x401b), nullptr);
    EXPECT_EQ(named(read.file, "ICE=4").icon, "ICE 1");
    EXPECT_EQ(named(read.file, "Reihe 2048 ÖBB").decoder, LocomotiveDecoder::Mfx);
}

TEST(LocomotiveFileTrainControl, ReportsDuplicateMfxSidAndUnknownKeysOnce) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveTrainControl);
    expectDiagnostics(
        read.diagnostics,
        {
            {2852, "duplicate sid 0x1b: locomotives 'ICE 1' (line 2793) and 'ICE=4' (line 2852)"},
            {1023, "unknown key '.blocks' in a locomotive record (21 times"},
            {1972, "unknown key '.spm' in a locomotive record (18 times"},
            {1973, "unknown key '.spa' in a locomotive record (12 times"},
            {1974, "unknown key '.ft' in a locomotive record (16 times"},
        });
}

TEST(LocomotiveFileTrainControl, WritingTheUnchangedModelGivesBackTheFile) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveTrainControl);
    EXPECT_EQ(read.file.write().serialize(), read.bytes);
}

TEST(LocomotiveFileTrainControl, ChangingOneFieldChangesOnlyItsLine) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveTrainControl);
    Locomotive& first = read.file.locomotives.front();
    first.name = "BR 85 007";
    EXPECT_EQ(changedLines(read.bytes, read.file.write().serialize()),
              std::vector<std::string>{"7:  .name=BR 85 007"});
}

TEST(LocomotiveFileTrainControl, NumbersKeepTheirHexFormAndDirectionIsRewritten) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveTrainControl);
    Locomotive& first = read.file.locomotives.front();
    first.address = 0x48;
    first.direction = TravelDirection::Forward;
    first.acceleration = 25;
    EXPECT_EQ(changedLines(read.bytes, read.file.write().serialize()),
              (std::vector<std::string>{"8:  .richtung=0", "10:  .adresse=0x48", "14:  .av=25"}));
}

TEST(LocomotiveFileTrainControl, SwitchingAFunctionOnAddsOneLineInItsBlock) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveTrainControl);
    read.file.locomotives.front().function(1)->value = 1;
    const std::string written = read.file.write().serialize();
    std::string expected = read.bytes;
    const std::string f1 = " .funktionen\n ..nr=1\n ..typ=7\n";
    const std::size_t at = expected.find(f1);
    ASSERT_NE(at, std::string::npos);
    expected.insert(at + f1.size(), " ..wert=1\n");
    EXPECT_EQ(written, expected);
}

TEST(LocomotiveFileTrainControl, AddedLocomotiveReadsBackTheSameAndKeepsNoFinalNewline) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveTrainControl);
    Locomotive added;
    added.uid = 0x4020;
    added.name = "BR 103 113-7";
    added.address = 0x20;
    added.decoder = LocomotiveDecoder::Mfx;
    added.sid = 0x20;
    added.mfxUid = 0x7ff01234;
    added.vMax = 200;
    for (int number = 0; number < 3; ++number)
        added.functions.push_back(Function{number, number == 0 ? 1 : 0, number == 2 ? -1 : 0, 0, {}});
    read.file.locomotives.push_back(added);
    const std::string written = read.file.write().serialize();
    EXPECT_EQ(written.substr(0, read.bytes.size()), read.bytes);
    EXPECT_EQ(written.substr(read.bytes.size()),
              "\nlokomotive\n .uid=0x4020\n .name=BR 103 113-7\n .adresse=0x20\n"
              " .typ=mfx\n .sid=0x20\n .mfxuid=0x7ff01234\n .vmax=200\n"
              " .funktionen\n ..nr=0\n ..typ=1\n .funktionen\n ..nr=1\n"
              " .funktionen\n ..nr=2\n ..dauer=-1");
    ReadFile again = readLocomotives(written);
    expectSameLocomotives(read.file, again.file);
    EXPECT_EQ(again.file.locomotives.back().functions[2].trigger(), FunctionTrigger::Momentary);
}

TEST(LocomotiveFileTrainControl, RemovedLocomotiveLeavesTheOthersUntouched) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveTrainControl);
    ASSERT_EQ(read.file.locomotives[1].name, "F7 endevogn");
    read.file.locomotives.erase(read.file.locomotives.begin() + 1);
    const std::string written = read.file.write().serialize();
    std::string expected = read.bytes;
    const std::size_t start = expected.find("lokomotive\n .name=F7 endevogn\n");
    const std::size_t end = expected.find("lokomotive\n .name=BR220 007-9 Ole\n");
    ASSERT_NE(start, std::string::npos);
    expected.erase(start, end - start);
    EXPECT_EQ(written, expected);
    expectSameLocomotives(read.file, readLocomotives(written).file);
}

TEST(LocomotiveFileTrainControl, FunctionAddedToTheLastLocomotiveEndsTheFileWithoutNewline) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveTrainControl);
    Locomotive& last = read.file.locomotives.back();
    ASSERT_EQ(last.name, "ABnsNoFunc");
    ASSERT_TRUE(last.functions.empty());
    last.functions.push_back(Function{0, 1, 0, 1, {}});
    const std::string written = read.file.write().serialize();
    EXPECT_EQ(written, read.bytes + "\n .funktionen\n ..nr=0\n ..typ=1\n ..wert=1");
    expectSameLocomotives(read.file, readLocomotives(written).file);
}

TEST(LocomotiveFileTrainControl, JsonListsEveryLocomotive) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveTrainControl);
    const std::string json = toJson(read.file);
    EXPECT_NE(json.find("\"locomotiveCount\": 108"), std::string::npos);
    EXPECT_NE(json.find("\"functionCount\": 1712"), std::string::npos);
    EXPECT_NE(json.find("\"name\": \"1043 006-4 ÖBB\""), std::string::npos);
    EXPECT_NE(json.find("\"inTraction\": \"0x2c01\""), std::string::npos);
}

// --- Edits on the structure --------------------------------------------------------------------

TEST(LocomotiveFileEdits, ReorderedFunctionsAreWrittenInTheirNewOrder) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveGbert);
    std::vector<Function>& functions = read.file.locomotives[2].functions;
    std::reverse(functions.begin(), functions.end());
    ReadFile again = rewritten(read.file);
    expectSameLocomotives(read.file, again.file);
    EXPECT_EQ(again.file.locomotives[2].functions.front().number, 15);
}

TEST(LocomotiveFileEdits, TractionMembersCvRowsAndMfxAddressCanBeAddedAndRemoved) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveTrainControl);
    Locomotive* unit = &named(read.file, "OBB 1043");
    unit->traction.pop_back();
    unit->traction.push_back(TractionMember{0x400c, "BR 78 054", {}});
    unit->cvRows.push_back(CvRow{1, "Adresse", 72, 0, {}});
    unit->mfxAddress = MfxAddress{2, 3, 136, 78, 79, 117, 16, 21, {}};
    ReadFile again = rewritten(read.file);
    expectSameLocomotives(read.file, again.file);
    const std::string written = read.file.write().serialize();
    EXPECT_NE(written.find(" .traktion\n ..lok=0x400c\n ..lokname=BR 78 054\n"), std::string::npos);
    EXPECT_NE(written.find(" .prg\n ..adresse=1\n ..name=Adresse\n ..wert=72\n ..maske=0\n"),
              std::string::npos);

    unit = &named(again.file, "OBB 1043");
    unit->traction.clear();
    unit->cvRows.clear();
    unit->mfxAddress.reset();
    ReadFile third = rewritten(again.file);
    EXPECT_EQ(third.bytes.find("traktion"), std::string::npos);
    EXPECT_EQ(third.bytes.find(".prg"), std::string::npos);
    EXPECT_EQ(third.bytes.find("mfxAdr"), std::string::npos);
}

} // namespace
} // namespace stellwerk::cs2config::test
