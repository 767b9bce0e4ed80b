// lokomotive.cs2 as real stations write it: the corpus files, their quirks, and edits that must
// change only what they change.
#include "cs2config/LocomotiveFile.h"

#include "ConfigTestSupport.h"
#include "cs2config/JsonWriter.h"
#include "cs2config/LocomotiveJson.h"
#include "cs2config/LocomotiveValues.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace stellwerk::cs2config::test {
namespace {

struct ReadFile {
    std::string bytes;
    Diagnostics diagnostics;
    LocomotiveFile file;
};

ReadFile readLocomotives(std::string bytes, std::string name = "lokomotive.cs2") {
    ReadFile read{std::move(bytes), Diagnostics(std::move(name)), {}};
    const Document document = Document::parse(read.bytes, read.diagnostics);
    read.file = LocomotiveFile::read(document, read.diagnostics);
    return read;
}

ReadFile readCorpusLocomotives(std::string_view path) {
    return readLocomotives(readCorpus(path));
}

// Every diagnostic as "line: message; action", for failure messages.
std::string listed(const Diagnostics& diagnostics) {
    return diagnostics.formatAll();
}

// Expects exactly these diagnostics, in order: the line and a part of the message.
void expectDiagnostics(const Diagnostics& diagnostics,
                       const std::vector<std::pair<int, std::string>>& expected) {
    ASSERT_EQ(diagnostics.items().size(), expected.size()) << listed(diagnostics);
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(diagnostics.items()[i].line, expected[i].first) << listed(diagnostics);
        EXPECT_NE(diagnostics.items()[i].message.find(expected[i].second), std::string::npos)
            << "expected '" << expected[i].second << "' in: " << diagnostics.items()[i].message;
    }
}

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

// The lines that differ between two texts of the same length in lines.
std::vector<std::string> changedLines(const std::string& before, const std::string& after) {
    const std::vector<std::string> a = splitLines(before);
    const std::vector<std::string> b = splitLines(after);
    EXPECT_EQ(a.size(), b.size());
    std::vector<std::string> changed;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
        if (a[i] != b[i])
            changed.push_back(std::to_string(i + 1) + ": " + b[i]);
    return changed;
}

// All typed fields of a locomotive (not where it came from), to compare a model with its re-read.
std::string typed(const Locomotive& locomotive) {
    JsonWriter json(false);
    writeLocomotiveJson(json, {}, locomotive);
    return std::regex_replace(json.text(), std::regex("\"line\":[0-9]+,"), "");
}

void expectSameLocomotives(const LocomotiveFile& expected, const LocomotiveFile& actual) {
    ASSERT_EQ(expected.locomotives.size(), actual.locomotives.size());
    for (std::size_t i = 0; i < expected.locomotives.size(); ++i)
        EXPECT_EQ(typed(expected.locomotives[i]), typed(actual.locomotives[i])) << "locomotive " << i;
}

// Writes the model and reads the result again.
ReadFile rewritten(const LocomotiveFile& file) {
    return readLocomotives(file.write().serialize());
}

std::size_t countDecoder(const LocomotiveFile& file, LocomotiveDecoder decoder) {
    return static_cast<std::size_t>(
        std::count_if(file.locomotives.begin(), file.locomotives.end(),
                      [decoder](const Locomotive& l) { return l.decoder == decoder; }));
}

std::size_t countFunctions(const LocomotiveFile& file, auto predicate) {
    std::size_t count = 0;
    for (const Locomotive& locomotive : file.locomotives)
        count += static_cast<std::size_t>(
            std::count_if(locomotive.functions.begin(), locomotive.functions.end(), predicate));
    return count;
}

Locomotive& named(LocomotiveFile& file, std::string_view name) {
    const auto found = std::find_if(file.locomotives.begin(), file.locomotives.end(),
                                    [name](const Locomotive& l) { return l.name == name; });
    EXPECT_NE(found, file.locomotives.end()) << name;
    return *found;
}

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
