// lokomotive.cs2 as other stations and programs write it: GBert's older format, srseii's duplicates, a
// corrupted file and a CS3-native one; what they read as, what is reported, and edits that keep the quirks.

#include "ConfigTestSupport.h"
#include "LocomotiveFileTestSupport.h"
#include "cs2config/LocomotiveFile.h"
#include "cs2config/LocomotiveValues.h"

#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace stellwerk::cs2config::test {
namespace {

using namespace locofile;

// --- GBert's file: older format, empty first record, mmm2_lok, ..vorwaerts/..rueckwaerts ------

TEST(LocomotiveFileGbert, ReadsTwentyOneRecordsOneOfThemEmpty) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveGbert);
    const LocomotiveFile& file = read.file;
    ASSERT_EQ(file.locomotives.size(), 21u); // 20 locomotives and the empty placeholder first
    EXPECT_TRUE(file.locomotives.front().isEmpty());
    EXPECT_EQ(std::count_if(file.locomotives.begin(), file.locomotives.end(),
                            [](const Locomotive& l) { return !l.isEmpty(); }),
              20);
    EXPECT_EQ(file.functionCount(), 336u); // 21 x F0-F15
    EXPECT_EQ(countDecoder(file, LocomotiveDecoder::None), 1u);
    EXPECT_EQ(countDecoder(file, LocomotiveDecoder::Mm2Prg), 11u);
    EXPECT_EQ(countDecoder(file, LocomotiveDecoder::Mmm2Lok), 5u);
    EXPECT_EQ(countDecoder(file, LocomotiveDecoder::Mfx), 4u);
    ASSERT_TRUE(file.version);
    EXPECT_EQ(file.version->major, 0);
    EXPECT_EQ(file.version->minor, 1);
    EXPECT_EQ(file.session, 1);
}

TEST(LocomotiveFileGbert, ReadsTheOlderXprotokollKey) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveGbert);
    Locomotive& locomotive = read.file.locomotives[1];
    EXPECT_EQ(locomotive.name, "Default");
    EXPECT_EQ(locomotive.extendedProtocol, 0);
    EXPECT_EQ(locomotive.tachoMax, 320);
    locomotive.extendedProtocol = 2;
    EXPECT_EQ(changedLines(read.bytes, read.file.write().serialize()),
              std::vector<std::string>{"158:  .xprotokoll=2"});
}

TEST(LocomotiveFileGbert, KeepsVorwaertsAndRueckwaertsWhenAFunctionChanges) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveGbert);
    Function* f0 = read.file.locomotives[1].function(0);
    ASSERT_NE(f0, nullptr);
    EXPECT_NE(f0->source.find("vorwaerts"), nullptr);
    EXPECT_EQ(f0->icon, 1);
    f0->icon = 2;
    f0->value = 1;
    EXPECT_EQ(changedLines(read.bytes, read.file.write().serialize()),
              (std::vector<std::string>{"164:  ..typ=2", "166:  ..wert=1"}));
}

TEST(LocomotiveFileGbert, ReportsTheEmptyRecordAndSidsSharedByMfxLocomotives) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveGbert);
    expectDiagnostics(read.diagnostics,
                      {
                          {7, "empty locomotive record (no name, uid 0)"},
                          {2424, "duplicate sid 0x1: locomotives '64 304' (line 2290) and '212 074-9'"},
                          {2558, "duplicate sid 0x1: locomotives '64 304' (line 2290) and '146 240-7'"},
                          {2692, "duplicate sid 0x1: locomotives '64 304' (line 2290) and '335 105-3'"},
                          {26, "unknown key '.stand' in a locomotive record (21 times"},
                          {27, "unknown key '.fahrt' in a locomotive record (21 times"},
                      });
}

TEST(LocomotiveFileGbert, WritingTheUnchangedModelGivesBackTheFile) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveGbert);
    EXPECT_EQ(read.file.write().serialize(), read.bytes);
}

// --- srseii: duplicates, .richtung=4294967295, .funktionen_2 ------------------------------------

TEST(LocomotiveFileSrseii, ReadsNineLocomotivesAndTheirFunctions) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveSrseii);
    EXPECT_EQ(read.file.locomotives.size(), 9u);
    EXPECT_EQ(read.file.functionCount(), 160u); // 9 x F0-F15 and F16-F31 of one loco
    EXPECT_EQ(std::count_if(read.file.locomotives.begin(), read.file.locomotives.end(),
                            [](const Locomotive& l) { return l.direction == TravelDirection::Unknown; }),
              8);
}

TEST(LocomotiveFileSrseii, NumbersFunctionsInFunktionen2FromSixteen) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveSrseii);
    const Locomotive& locomotive = named(read.file, "50 2640 DB");
    ASSERT_EQ(locomotive.functions.size(), 32u);
    for (int number = 0; number < 32; ++number) {
        EXPECT_EQ(locomotive.functions[static_cast<std::size_t>(number)].number, number);
        EXPECT_EQ(locomotive.functions[static_cast<std::size_t>(number)].source.key(),
                  number < 16 ? "funktionen" : "funktionen_2");
    }
    EXPECT_EQ(locomotive.function(19)->icon, 133);
    EXPECT_EQ(locomotive.function(23)->icon, 1);
}

TEST(LocomotiveFileSrseii, ReportsEveryDuplicateWithBothLines) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveSrseii);
    expectDiagnostics(
        read.diagnostics,
        {
            {292, "duplicate uid 0x4005: locomotives '261 841-1 DB' (line 63) and '260 417-1 DB' (line 292)"},
            {295, "duplicate sid 0x5: locomotives '261 841-1 DB' (line 66) and '260 417-1 DB' (line 295)"},
            {296, "duplicate mfxuid 0x73f4865b: locomotives '261 841-1 DB' (line 67) and '260 417-1 DB'"},
            {357, "duplicate uid 0x4006: locomotives '50 2640 DB' (line 128) and 'Re 460 017-7' (line 357)"},
            {360, "duplicate sid 0x6: locomotives '50 2640 DB' (line 131) and 'Re 460 017-7' (line 360)"},
            {407, "duplicate uid 0x4007: locomotives 'ICE Amtrak I' (line 237) and 'Re 460 017- (2)'"},
            {410, "duplicate sid 0x7: locomotives 'ICE Amtrak I' (line 240) and 'Re 460 017- (2)'"},
            {522, "duplicate uid 0x1: locomotives 'Lokliste' (line 9) and 'ABC' (line 522)"},
            {20, "unknown key '.stand' in a locomotive record (9 times"},
            {21, "unknown key '.fahrt' in a locomotive record (9 times"},
            {62, "direction '.richtung=4294967295' is -1 (not set) (8 times"},
        });
}

TEST(LocomotiveFileSrseii, UnsetDirectionStaysUntilADirectionIsSet) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveSrseii);
    EXPECT_EQ(read.file.write().serialize(), read.bytes);
    read.file.locomotives[1].direction = TravelDirection::Backward;
    EXPECT_EQ(changedLines(read.bytes, read.file.write().serialize()),
              std::vector<std::string>{"62:  .richtung=1"});
}

TEST(LocomotiveFileSrseii, NewFunctionsFromF16GoWhereTheLocomotiveKeepsThem) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveSrseii);
    Locomotive& cs3Style = named(read.file, "50 2640 DB");
    cs3Style.functions.pop_back(); // F31 removed and added again
    cs3Style.functions.push_back(Function{31, 5, 0, 0, {}});
    Locomotive& cs2Style = named(read.file, "Lokliste");
    cs2Style.functions.push_back(Function{16, 5, 0, 0, {}});
    ReadFile again = rewritten(read.file);
    EXPECT_EQ(named(again.file, "50 2640 DB").function(31)->source.key(), "funktionen_2");
    EXPECT_EQ(named(again.file, "Lokliste").function(16)->source.key(), "funktionen");
    expectSameLocomotives(read.file, again.file);
}

// --- The corrupted file: a truncated header line in the middle ----------------------------------

TEST(LocomotiveFileCorrupted, ReadsEveryLocomotiveAroundTheDamagedLine) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveCorrupted);
    ASSERT_EQ(read.file.locomotives.size(), 5u);
    EXPECT_TRUE(read.file.locomotives[0].isEmpty()); // "lokomotive" whose next line is " komotive]"
    EXPECT_EQ(read.file.locomotives[1].name, "ABC");
    EXPECT_EQ(read.file.locomotives[2].name, "BR86");
    EXPECT_EQ(read.file.locomotives[3].name, "BR043903-4");
    EXPECT_EQ(read.file.locomotives[4].name, "E118013-2");
    EXPECT_EQ(read.file.locomotives[3].decoder, LocomotiveDecoder::Mmm2Lok);
    EXPECT_EQ(read.file.locomotives[2].direction, TravelDirection::Unknown); // .richtung=-1
    EXPECT_EQ(read.file.functionCount(), 64u);
}

TEST(LocomotiveFileCorrupted, ReportsTheDamagedLineTheEmptyRecordAndOddValues) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveCorrupted);
    expectDiagnostics(read.diagnostics, {
                                            {7, "unreadable line ' komotive]'"},
                                            {6, "empty locomotive record"},
                                            {9, "unknown key '.dv' in a locomotive record (4 times"},
                                            {115, "direction '.richtung=-1' is -1 (not set) (3 times"},
                                        });
}

TEST(LocomotiveFileCorrupted, EditsKeepTheDamagedLine) {
    ReadFile read = readCorpusLocomotives(corpus::lokomotiveCorrupted);
    EXPECT_EQ(read.file.write().serialize(), read.bytes);
    read.file.locomotives[1].name = "ABC 2";
    EXPECT_EQ(changedLines(read.bytes, read.file.write().serialize()),
              std::vector<std::string>{"11:  .name=ABC 2"});
}

// --- The CS3-native single-loco file ----------------------------------------------------------

TEST(LocomotiveFileCs3, ReadsWhatMatchesTheCs2FormatAndSaysSoOnce) {
    ReadFile read = readCorpusLocomotives(corpus::cs3Loco);
    EXPECT_TRUE(read.file.cs3Native);
    expectDiagnostics(
        read.diagnostics,
        {{6, "CS3-native locomotive file ('.dectyp', '#20' escapes), not the CS2 format; keys the CS2 "
             "format does not have: .artikelnr, .spa, ..typ2; CS2 keys it lacks: .adresse"}});
    ASSERT_EQ(read.file.locomotives.size(), 1u);
    const Locomotive& locomotive = read.file.locomotives.front();
    EXPECT_EQ(locomotive.name, "260 417-1 DB");
    EXPECT_EQ(locomotive.previousName, "260 417-1 DB");
    EXPECT_EQ(locomotive.icon, "/usr/local/cs3/lokicons/mSD3_Logo");
    EXPECT_EQ(locomotive.uid, 0x4006u);
    EXPECT_EQ(locomotive.decoder, LocomotiveDecoder::Mfx);
    EXPECT_EQ(locomotive.mfxUid, 0x73f4865bu);
    EXPECT_EQ(locomotive.tachoMax, 90);
    ASSERT_EQ(locomotive.functions.size(), 32u); // F0-F31, all in .funktionen
    EXPECT_EQ(locomotive.functions[31].number, 31);
    EXPECT_EQ(locomotive.function(7)->icon, 138);
    ASSERT_TRUE(locomotive.mfxAddress);
    EXPECT_EQ(locomotive.mfxAddress->target, 2);
    EXPECT_EQ(locomotive.mfxAddress->name, 3);
    EXPECT_EQ(locomotive.mfxAddress->address, 324);
    EXPECT_EQ(locomotive.mfxAddress->acceleration, 178);
    EXPECT_EQ(locomotive.mfxAddress->speedTable, 179);
    EXPECT_EQ(locomotive.mfxAddress->volume, 301);
    EXPECT_EQ(locomotive.mfxAddress->functionCount, 16);
    EXPECT_EQ(locomotive.mfxAddress->functions, 65);
}

TEST(LocomotiveFileCs3, WritesNamesEscapedAgain) {
    ReadFile read = readCorpusLocomotives(corpus::cs3Loco);
    EXPECT_EQ(read.file.write().serialize(), read.bytes);
    read.file.locomotives.front().name = "260 417-1 DB/2";
    read.file.locomotives.front().decoder = LocomotiveDecoder::Dcc;
    EXPECT_EQ(changedLines(read.bytes, read.file.write().serialize()),
              (std::vector<std::string>{"3:  .name=260#20417-1#20DB#2F2", "6:  .dectyp=dcc"}));
}

// Issue 11 (found by fuzzing): "#xx" escapes became arbitrary bytes. A CS3 escapes ASCII; escapes that
// form UTF-8 stay UTF-8, any other byte above 0x7F is its Latin-1 character: the text is always UTF-8.
TEST(LocomotiveFileCs3, EscapesAlwaysDecodeToUtf8) {
    EXPECT_EQ(loco::cs3Unescape("260#20417-1#20DB#2F2"), "260 417-1 DB/2");
    EXPECT_EQ(loco::cs3Unescape("Gro#DFe"), "Gro\u00dfe");
    EXPECT_EQ(loco::cs3Unescape("#cc"), "\u00cc");
    EXPECT_EQ(loco::cs3Unescape("B#C3#A4r"), "B\u00e4r");
    EXPECT_EQ(loco::cs3Unescape("#C3#20"), "\u00c3 ");
    EXPECT_EQ(loco::cs3Unescape("#2"), "#2");
    EXPECT_EQ(loco::cs3Unescape("#"), "#");
}

} // namespace
} // namespace stellwerk::cs2config::test
