// magnetartikel.cs2 and the MS2's maginfo stream as typed accessories: the document's examples, the two
// corpus files, writing back byte for byte, and the diagnostics.

#include "cs2config/AccessoryFile.h"

#include "ConfigTestSupport.h"
#include "cs2config/AccessoryAddressCheck.h"
#include "cs2config/AccessoryType.h"

#include <map>
#include <random>

namespace stellwerk::cs2config::test {
namespace {

// 8.2: the document's magnetartikel.cs2 example.
constexpr std::string_view documentMagnetartikel = "[magnetartikel]\n"
                                                   "version\n"
                                                   ".major=0\n"
                                                   ".minor=1\n"
                                                   "artikel\n"
                                                   ".id=1\n"
                                                   ".name=src\n"
                                                   ".typ=lichtsignal_HP012_SH01\n"
                                                   ".stellung=2\n"
                                                   ".schaltzeit=200\n"
                                                   ".ungerade=0\n"
                                                   ".dectyp=mm2\n";

// 8.6: the document's maginfo stream.
constexpr std::string_view documentMaginfo = "[magnetartikel]\n"
                                             "artikel\n"
                                             "  .id=3\n"
                                             "  .name=1.3\n"
                                             "  .typ=rechtsweiche\n"
                                             "  .schaltzeit=200\n"
                                             "  .dectyp=mm2\n"
                                             "artikel\n"
                                             "  .id=4\n"
                                             "  .name=1.4\n"
                                             "  .typ=entkupplungsgleis\n"
                                             "  .schaltzeit=200\n"
                                             "  .dectyp=mm2\n";

using Read = ReadModel<AccessoryFile>;

Read readText(std::string_view text) {
    return readAs<AccessoryFile>(text, "magnetartikel.cs2");
}

Read readCorpusFile(std::string_view path) {
    return readText(readCorpus(path));
}

std::map<std::string, int> countBy(const AccessoryFile& file, std::string Accessory::*field) {
    std::map<std::string, int> counts;
    for (const Accessory& accessory : file.accessories)
        ++counts[accessory.*field];
    return counts;
}

void expectSameAccessories(const std::vector<Accessory>& actual, const std::vector<Accessory>& expected) {
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < actual.size(); ++i) {
        SCOPED_TRACE("accessory " + std::to_string(i));
        EXPECT_EQ(actual[i].id, expected[i].id);
        EXPECT_EQ(actual[i].name, expected[i].name);
        EXPECT_EQ(actual[i].type, expected[i].type);
        EXPECT_EQ(actual[i].position, expected[i].position);
        EXPECT_EQ(actual[i].switchTimeMs, expected[i].switchTimeMs);
        EXPECT_EQ(actual[i].secondOutput, expected[i].secondOutput);
        EXPECT_EQ(actual[i].decoder, expected[i].decoder);
        EXPECT_EQ(actual[i].protocol, expected[i].protocol);
    }
}

const Accessory& byId(const AccessoryFile& file, std::int64_t id) {
    for (const Accessory& accessory : file.accessories)
        if (accessory.id == id)
            return accessory;
    throw std::out_of_range("no accessory " + std::to_string(id));
}

bool mentions(const Diagnostics& diagnostics, std::string_view text) {
    return diagnostics.formatAll().find(text) != std::string::npos;
}

TEST(AccessoryFile, DocumentExampleIsRead) {
    Read read = readText(documentMagnetartikel);
    EXPECT_TRUE(read.diagnostics.empty()) << read.diagnostics.formatAll();
    EXPECT_EQ(read.file.versionMajor, 0);
    EXPECT_EQ(read.file.versionMinor, 1);
    ASSERT_EQ(read.file.accessories.size(), 1u);
    const Accessory& signal = read.file.accessories[0];
    EXPECT_EQ(signal.id, 1);
    EXPECT_EQ(signal.name, "src");
    EXPECT_EQ(signal.type, "lichtsignal_HP012_SH01");
    EXPECT_EQ(signal.position, 2);
    EXPECT_EQ(signal.switchTimeMs, 200);
    EXPECT_FALSE(signal.secondOutput);
    EXPECT_EQ(signal.protocol, "mm2");
    EXPECT_EQ(signal.decoder, "");
    EXPECT_EQ(signal.addressCount(), 2);
    EXPECT_EQ(signal.lineNumber(), 5);
    EXPECT_EQ(read.file.write().serialize(), documentMagnetartikel);
}

TEST(AccessoryFile, TrainControlCorpusCounts) {
    Read read = readCorpusFile(corpus::magnetartikelTrainControl);
    const AccessoryFile& file = read.file;
    ASSERT_EQ(file.accessories.size(), 127u);
    EXPECT_EQ(file.versionMajor, std::nullopt);
    EXPECT_EQ(file.versionMinor, 1);
    const std::map<std::string, int> types = {
        {"digitaldrehscheibe", 1}, {"dreiwegweiche", 1},        {"entkupplungsgleis", 16},
        {"formsignal_HP012", 2},   {"lichtsignal_HP01", 45},    {"lichtsignal_SH01", 2},
        {"linksweiche", 29},       {"rechtsweiche", 25},        {"std_rot", 2},
        {"std_rot_gruen", 2},      {"urc_lichtsignal_HP01", 2},
    };
    EXPECT_EQ(countBy(file, &Accessory::type), types);
    const std::map<std::string, int> decoders = {{"ein_neu", 11}, {"mehr_alt", 103}, {"mehr_neu", 13}};
    EXPECT_EQ(countBy(file, &Accessory::decoder), decoders);
    const std::map<std::string, int> protocols = {{"dcc", 1}, {"mm2", 126}};
    EXPECT_EQ(countBy(file, &Accessory::protocol), protocols);
    EXPECT_EQ(byId(file, 121).protocol, "dcc");
    EXPECT_EQ(byId(file, 225).addressCount(), 16);
    EXPECT_EQ(byId(file, 5).addressCount(), 2);
    EXPECT_EQ(byId(file, 5).position, 2);
    EXPECT_EQ(byId(file, 108).name, "");
    EXPECT_EQ(byId(file, 23).switchTimeMs, std::nullopt);
    EXPECT_EQ(byId(file, 27).switchTimeMs, 250);
}

TEST(AccessoryFile, TrainControlPositionsAndSwitchTimes) {
    const AccessoryFile file = readCorpusFile(corpus::magnetartikelTrainControl).file;
    std::map<std::int64_t, int> positions;
    std::map<std::int64_t, int> switchTimes;
    for (const Accessory& accessory : file.accessories) {
        ++positions[accessory.position];
        ++switchTimes[accessory.switchTimeMs.value_or(-1)];
    }
    EXPECT_EQ(positions, (std::map<std::int64_t, int>{{0, 69}, {1, 55}, {2, 1}, {3, 2}}));
    EXPECT_EQ(switchTimes, (std::map<std::int64_t, int>{{-1, 3}, {200, 118}, {250, 2}, {300, 1}, {350, 3}}));
}

TEST(AccessoryFile, TrainControlUncouplerPairsShareTheirIdLegally) {
    Read read = readCorpusFile(corpus::magnetartikelTrainControl);
    std::vector<std::int64_t> shared;
    for (const Accessory& accessory : read.file.accessories)
        if (accessory.secondOutput) {
            shared.push_back(accessory.id);
            EXPECT_EQ(accessory.type, "entkupplungsgleis");
            EXPECT_EQ(accessory.name, std::to_string(accessory.id) + "b");
        }
    EXPECT_EQ(shared, (std::vector<std::int64_t>{29, 30, 31, 32, 89, 90, 91, 92}));
    EXPECT_FALSE(mentions(read.diagnostics, "duplicate")) << read.diagnostics.formatAll();
}

// std_rot 108 and 110 sit on the second address of the formsignal_HP012 articles 107 and 109 (whose
// positions 0, 1, 3 leave that address's first output free); the overlap is reported, both are kept.
TEST(AccessoryFile, TrainControlSecondAddressesOfSignalsAreReported) {
    Read read = readCorpusFile(corpus::magnetartikelTrainControl);
    ASSERT_EQ(read.diagnostics.count(), 2u) << read.diagnostics.formatAll();
    EXPECT_EQ(read.diagnostics.items()[0].line, 853);
    EXPECT_EQ(read.diagnostics.items()[1].line, 866);
    EXPECT_FALSE(read.diagnostics.hasErrors());
    EXPECT_NE(
        read.diagnostics.items()[0].message.find("accessory 108 (std_rot, line 853) uses address 108, which "
                                                 "accessory 107 (formsignal_HP012, line 845) also takes"),
        std::string::npos)
        << read.diagnostics.items()[0].message;
    EXPECT_EQ(read.diagnostics.items()[0].action, "both kept");
}

TEST(AccessoryFile, GbertCorpusCounts) {
    Read read = readCorpusFile(corpus::magnetartikelGbert);
    EXPECT_TRUE(read.diagnostics.empty()) << read.diagnostics.formatAll();
    const AccessoryFile& file = read.file;
    ASSERT_EQ(file.accessories.size(), 13u);
    const std::map<std::string, int> types = {
        {"linksweiche", 3}, {"rechtsweiche", 3}, {"urc_lichtsignal_HP012_SH01", 7}};
    EXPECT_EQ(countBy(file, &Accessory::type), types);
    EXPECT_EQ(countBy(file, &Accessory::decoder),
              (std::map<std::string, int>{{"mehr_alt", 7}, {"mehr_neu", 6}}));
    EXPECT_EQ(countBy(file, &Accessory::protocol), (std::map<std::string, int>{{"mm2", 13}}));
    std::vector<std::int64_t> signalIds;
    for (const Accessory& accessory : file.accessories)
        if (accessory.addressCount() == 2) {
            signalIds.push_back(accessory.id);
            EXPECT_EQ(accessory.position, 3);
        }
    EXPECT_EQ(signalIds, (std::vector<std::int64_t>{7, 9, 11, 13, 15, 17, 19}));
}

TEST(AccessoryFile, CorpusFilesAreWrittenBackByteForByte) {
    for (std::string_view path : {corpus::magnetartikelTrainControl, corpus::magnetartikelGbert}) {
        const std::string bytes = readCorpus(path);
        EXPECT_EQ(readText(bytes).file.write().serialize(), bytes) << path;
    }
}

TEST(AccessoryFile, ChangingOnePositionChangesOnlyThatLine) {
    const std::string bytes = readCorpus(corpus::magnetartikelTrainControl);
    AccessoryFile file = readText(bytes).file;
    Accessory& turnout = file.accessories.at(1);
    ASSERT_EQ(turnout.id, 2);
    turnout.position = 0;
    turnout.name = "Einfahrt West";
    const int stellung = turnout.source.find("stellung")->lineNumber();
    const int name = turnout.source.find("name")->lineNumber();
    const std::string expected =
        withLine(withLine(bytes, stellung, " .stellung=0"), name, " .name=Einfahrt West");
    EXPECT_EQ(file.write().serialize(), expected);
}

TEST(AccessoryFile, MissingLinesAreAddedOnlyWhenTheValueNeedsThem) {
    Read read = readText("[magnetartikel]\nartikel\n .id=0x3\n .typ=rechtsweiche\n .dectyp=mm2\n");
    Accessory& turnout = read.file.accessories.at(0);
    turnout.id = 3;
    turnout.secondOutput = false;
    EXPECT_EQ(read.file.write().serialize(),
              "[magnetartikel]\nartikel\n .id=0x3\n .typ=rechtsweiche\n .dectyp=mm2\n");
    turnout.position = 1;
    turnout.switchTimeMs = 200;
    EXPECT_EQ(read.file.write().serialize(), "[magnetartikel]\nartikel\n .id=0x3\n .typ=rechtsweiche\n "
                                             ".dectyp=mm2\n .stellung=1\n .schaltzeit=200\n");
}

TEST(AccessoryFile, AddedAndRemovedAccessoriesReadBackTheSame) {
    AccessoryFile file = readCorpusFile(corpus::magnetartikelGbert).file;
    file.accessories.erase(file.accessories.begin() + 2);
    Accessory added;
    added.id = 21;
    added.name = "Ausfahrt";
    added.type = "dreiwegweiche";
    added.position = 2;
    added.switchTimeMs = 250;
    added.decoder = "mehr_neu";
    added.protocol = "dcc";
    file.accessories.push_back(added);
    Accessory uncoupler;
    uncoupler.id = 23;
    uncoupler.type = "entkupplungsgleis";
    uncoupler.secondOutput = true;
    file.accessories.insert(file.accessories.begin(), uncoupler);

    const std::string written = file.write().serialize();
    Read again = readText(written);
    EXPECT_TRUE(again.diagnostics.empty()) << again.diagnostics.formatAll();
    expectSameAccessories(again.file.accessories, file.accessories);
    EXPECT_NE(written.find("artikel\n .id=23\n .typ=entkupplungsgleis\n .ungerade=1\n"), std::string::npos);
    EXPECT_NE(written.find(
                  "artikel\n .id=21\n .name=Ausfahrt\n .typ=dreiwegweiche\n .stellung=2\n .schaltzeit=250\n"
                  " .decoder=mehr_neu\n .dectyp=dcc\n"),
              std::string::npos);
    EXPECT_EQ(written.find(" .name=22\n"), std::string::npos);
}

TEST(AccessoryFile, NewFileIsWrittenInTheStationsStyle) {
    AccessoryFile file;
    file.versionMinor = 1;
    Accessory turnout;
    turnout.id = 1;
    turnout.name = "W1";
    turnout.type = "linksweiche";
    turnout.switchTimeMs = 200;
    turnout.decoder = "mehr_neu";
    turnout.protocol = "mm2";
    file.accessories.push_back(turnout);
    EXPECT_EQ(file.write().serialize(),
              "[magnetartikel]\nversion\n .minor=1\nartikel\n .id=1\n .name=W1\n"
              " .typ=linksweiche\n .schaltzeit=200\n .decoder=mehr_neu\n .dectyp=mm2\n");
}

TEST(AccessoryFile, AccessoryAddedToAFileWithoutFinalNewline) {
    Read read = readText("[magnetartikel]\nartikel\n .id=1\n .typ=linksweiche");
    Accessory added;
    added.id = 2;
    added.type = "rechtsweiche";
    read.file.accessories.push_back(added);
    EXPECT_EQ(read.file.write().serialize(),
              "[magnetartikel]\nartikel\n .id=1\n .typ=linksweiche\nartikel\n .id=2\n .typ=rechtsweiche");
}

TEST(AccessoryFile, UnknownTypesAndKeysAreReportedOnce) {
    Read read = readText("[magnetartikel]\nartikel\n .id=1\n .typ=drehscheibe_mfx\n .farbe=rot\n"
                         "artikel\n .id=2\n .typ=drehscheibe_mfx\n .farbe=gelb\n"
                         "gruppe\n .id=1\ngruppe\n .id=2\n");
    ASSERT_EQ(read.diagnostics.count(), 3u) << read.diagnostics.formatAll();
    EXPECT_EQ(read.diagnostics.items()[0].line, 5);
    EXPECT_EQ(read.diagnostics.items()[0].message, "unknown key '.farbe' in artikel records");
    EXPECT_EQ(read.diagnostics.items()[1].line, 4);
    EXPECT_EQ(read.diagnostics.items()[1].message, "unknown accessory type 'drehscheibe_mfx'");
    EXPECT_EQ(read.diagnostics.items()[2].line, 10);
    EXPECT_EQ(read.diagnostics.items()[2].message, "unknown record 'gruppe'");
    EXPECT_EQ(read.file.accessories.at(1).addressCount(), 1);
    EXPECT_EQ(read.file.write().serialize(), read.file.document.serialize());
}

TEST(AccessoryFile, ValuesThatAreNotNumbersAreKept) {
    const std::string text = "[magnetartikel]\nartikel\n .id=4\n .typ=linksweiche\n .stellung=gerade\n"
                             " .schaltzeit=lang\nartikel\n .name=ohne Nummer\n .typ=linksweiche\n";
    Read read = readText(text);
    ASSERT_EQ(read.diagnostics.count(), 4u) << read.diagnostics.formatAll();
    EXPECT_EQ(read.diagnostics.items()[0].line, 5);
    EXPECT_EQ(read.diagnostics.items()[0].message,
              "value 'gerade' of .stellung in artikel record is not a number");
    EXPECT_EQ(read.diagnostics.items()[0].action, "kept unchanged; 0 used");
    EXPECT_EQ(read.diagnostics.items()[1].line, 6);
    EXPECT_EQ(read.diagnostics.items()[1].action, "kept unchanged; read as missing");
    EXPECT_EQ(read.diagnostics.items()[2].line, 7);
    EXPECT_EQ(read.diagnostics.items()[2].message, "artikel record without .id");
    EXPECT_EQ(read.diagnostics.items()[2].severity, Diagnostic::Severity::Error);
    EXPECT_EQ(read.diagnostics.items()[3].line, 7);
    EXPECT_EQ(read.diagnostics.items()[3].message,
              "accessory 0 (linksweiche, line 7) lies outside the keyboard addresses 1-2048");
    EXPECT_EQ(read.file.accessories.at(0).position, 0);
    EXPECT_EQ(read.file.accessories.at(0).switchTimeMs, std::nullopt);
    EXPECT_EQ(read.file.write().serialize(), text);
    read.file.accessories.at(0).position = 1;
    EXPECT_EQ(read.file.write().serialize(), withLine(text, 5, " .stellung=1"));
}

TEST(AccessoryFile, KeyWithoutValueIsReported) {
    Read read = readText("[magnetartikel]\nartikel\n .id\n .typ=linksweiche\n");
    ASSERT_EQ(read.diagnostics.count(), 2u) << read.diagnostics.formatAll();
    EXPECT_EQ(read.diagnostics.items()[0].line, 3);
    EXPECT_EQ(read.diagnostics.items()[0].message, ".id in artikel record has no value");
    EXPECT_EQ(read.diagnostics.items()[0].action, "kept unchanged; 0 used");
    EXPECT_EQ(read.file.write().serialize(), "[magnetartikel]\nartikel\n .id\n .typ=linksweiche\n");
}

TEST(AccessoryFile, KeyGivenTwiceIsReported) {
    Read read = readText("[magnetartikel]\nartikel\n .id=1\n .typ=linksweiche\n .stellung=1\n .stellung=0\n");
    ASSERT_EQ(read.diagnostics.count(), 1u) << read.diagnostics.formatAll();
    EXPECT_EQ(read.diagnostics.items()[0].line, 6);
    EXPECT_EQ(read.diagnostics.items()[0].message,
              "'.stellung' given twice in one of the artikel records (first at line 5)");
    EXPECT_EQ(read.file.accessories.at(0).position, 1);
}

TEST(AccessoryFile, DuplicateIdsAreReportedUnlessTheyAreTwoOutputsOfOneAddress) {
    Read read = readText("[magnetartikel]\n"
                         "artikel\n .id=5\n .typ=entkupplungsgleis\n"
                         "artikel\n .id=5\n .typ=entkupplungsgleis\n .ungerade=1\n"
                         "artikel\n .id=6\n .typ=rechtsweiche\n"
                         "artikel\n .id=6\n .typ=linksweiche\n"
                         "artikel\n .id=7\n .typ=std_rot\n"
                         "artikel\n .id=7\n .typ=std_gruen\n");
    ASSERT_EQ(read.diagnostics.count(), 2u) << read.diagnostics.formatAll();
    EXPECT_EQ(read.diagnostics.items()[0].line, 12);
    EXPECT_EQ(read.diagnostics.items()[0].message,
              "duplicate accessory id 6: accessory 6 (linksweiche, line 12) and "
              "accessory 6 (rechtsweiche, line 9)");
    EXPECT_EQ(read.diagnostics.items()[1].line, 18);
    EXPECT_EQ(read.file.accessories.size(), 6u);
}

TEST(AccessoryFile, OverlappingAddressesAndIdsOutsideTheKeyboardAreReported) {
    Read read = readText("[magnetartikel]\n"
                         "artikel\n .id=5\n .typ=dreiwegweiche\n"
                         "artikel\n .id=6\n .typ=linksweiche\n"
                         "artikel\n .id=0\n .typ=linksweiche\n"
                         "artikel\n .id=1024\n .typ=dreiwegweiche\n .dectyp=mm2\n"
                         "artikel\n .id=2000\n .typ=dreiwegweiche\n .dectyp=dcc\n");
    ASSERT_EQ(read.diagnostics.count(), 3u) << read.diagnostics.formatAll();
    EXPECT_EQ(read.diagnostics.items()[0].line, 5);
    EXPECT_EQ(
        read.diagnostics.items()[0].message,
        "accessory 6 (linksweiche, line 5) uses address 6, which accessory 5 (dreiwegweiche, line 2) also "
        "takes: it uses 2 addresses, 5-6");
    EXPECT_EQ(read.diagnostics.items()[1].line, 8);
    EXPECT_EQ(read.diagnostics.items()[1].message,
              "accessory 0 (linksweiche, line 8) lies outside the keyboard addresses 1-2048");
    EXPECT_EQ(read.diagnostics.items()[2].line, 11);
    EXPECT_EQ(read.diagnostics.items()[2].message,
              "accessory 1024 (dreiwegweiche, line 11) lies outside the keyboard addresses 1-1024");
}

TEST(AccessoryFile, PositionsATypeDoesNotHaveAreReported) {
    Read read = readText("[magnetartikel]\n"
                         "artikel\n .id=1\n .typ=dreiwegweiche\n .stellung=3\n"
                         "artikel\n .id=3\n .typ=formsignal_HP012\n .stellung=3\n"
                         "artikel\n .id=5\n .typ=formsignal_HP012\n .stellung=2\n"
                         "artikel\n .id=7\n .typ=rechtsweiche\n .stellung=-1\n");
    ASSERT_EQ(read.diagnostics.count(), 3u) << read.diagnostics.formatAll();
    EXPECT_EQ(read.diagnostics.items()[0].line, 5);
    EXPECT_EQ(read.diagnostics.items()[0].message,
              "position 3 of accessory 1 is not one of the positions of dreiwegweiche (0, 1, 2)");
    EXPECT_EQ(read.diagnostics.items()[1].line, 13);
    EXPECT_EQ(read.diagnostics.items()[1].message,
              "position 2 of accessory 5 is not one of the positions of formsignal_HP012 (0, 1, 3)");
    EXPECT_EQ(read.diagnostics.items()[2].line, 17);
}

TEST(AccessoryFile, UnknownProtocolAndMissingTypeAreReported) {
    Read read = readText("[magnetartikel]\nartikel\n .id=1\n .typ=linksweiche\n .dectyp=sx1\n"
                         "artikel\n .id=2\n .typ=linksweiche\n .dectyp=sx1\nartikel\n .id=3\n");
    ASSERT_EQ(read.diagnostics.count(), 2u) << read.diagnostics.formatAll();
    EXPECT_EQ(read.diagnostics.items()[0].line, 5);
    EXPECT_EQ(read.diagnostics.items()[0].message, "unknown decoder protocol .dectyp='sx1'");
    EXPECT_EQ(read.diagnostics.items()[1].line, 10);
    EXPECT_EQ(read.diagnostics.items()[1].message, "artikel without .typ");
}

TEST(AccessoryFile, JsonListsTheAccessoriesWithTheirSizes) {
    Read read =
        readText("[magnetartikel]\nversion\n .minor=1\nartikel\n .id=5\n .name=W \"5\"\n .typ=dreiwegweiche\n"
                 " .stellung=2\n .dectyp=mm2\n");
    EXPECT_EQ(toJson(read.file), R"({
  "file": "magnetartikel.cs2",
  "version": {
    "major": null,
    "minor": 1
  },
  "accessories": [
    {
      "line": 4,
      "id": 5,
      "name": "W \"5\"",
      "type": "dreiwegweiche",
      "knownType": true,
      "addresses": 2,
      "positions": 3,
      "position": 2,
      "switchTimeMs": null,
      "secondOutput": false,
      "decoder": "",
      "protocol": "mm2"
    }
  ]
}
)");
}

TEST(AccessoryFile, MaginfoExampleIsReadAsAccessories) {
    Read read = readText(documentMaginfo);
    EXPECT_TRUE(read.diagnostics.empty()) << read.diagnostics.formatAll();
    EXPECT_EQ(read.file.versionMinor, std::nullopt);
    ASSERT_EQ(read.file.accessories.size(), 2u);
    EXPECT_EQ(read.file.accessories[0].id, 3);
    EXPECT_EQ(read.file.accessories[0].name, "1.3");
    EXPECT_EQ(read.file.accessories[0].type, "rechtsweiche");
    EXPECT_EQ(read.file.accessories[1].type, "entkupplungsgleis");
    EXPECT_EQ(read.file.accessories[1].switchTimeMs, 200);
    EXPECT_EQ(read.file.accessories[1].protocol, "mm2");
    EXPECT_EQ(read.file.document.style().indent, "  ");
    EXPECT_EQ(read.file.write().serialize(), documentMaginfo);
}

// MS2 text streams pad their lines with spaces; the words the format defines are read without them.
TEST(AccessoryFile, MaginfoWithPaddedLinesIsRead) {
    const std::string padded = "[magnetartikel]\nartikel\n  .id=3  \n  .name=1.3 \n  .typ=rechtsweiche    \n"
                               "  .schaltzeit=200 \n  .dectyp=mm2     \n";
    Read read = readText(padded);
    EXPECT_TRUE(read.diagnostics.empty()) << read.diagnostics.formatAll();
    const Accessory& turnout = read.file.accessories.at(0);
    EXPECT_EQ(turnout.id, 3);
    EXPECT_EQ(turnout.name, "1.3 ");
    EXPECT_EQ(turnout.type, "rechtsweiche");
    EXPECT_EQ(turnout.switchTimeMs, 200);
    EXPECT_EQ(turnout.protocol, "mm2");
    EXPECT_EQ(read.file.write().serialize(), padded);
}

TEST(AccessoryFile, MaginfoIsWrittenLikeTheDocumentsExample) {
    Read read = readText(documentMaginfo);
    EXPECT_EQ(writeAccessoryInfo(read.file.accessories).serialize(), documentMaginfo);
}

TEST(AccessoryFile, MaginfoLeavesOutWhatTheMs2DoesNotGet) {
    const AccessoryFile file = readCorpusFile(corpus::magnetartikelGbert).file;
    const std::vector<Accessory> firstTwo(file.accessories.begin(), file.accessories.begin() + 2);
    EXPECT_EQ(writeAccessoryInfo(firstTwo).serialize(),
              "[magnetartikel]\nartikel\n  .id=1\n  .name=23\n  .typ=rechtsweiche\n  .schaltzeit=200\n  "
              ".dectyp=mm2\n"
              "artikel\n  .id=2\n  .name=13\n  .typ=linksweiche\n  .schaltzeit=200\n  .dectyp=mm2\n");
}

TEST(AccessoryType, EveryDocumentedTypeIsKnown) {
    const std::vector<std::string_view> documented = {
        "std_rot_gruen",
        "std_rot",
        "std_gruen",
        "entkupplungsgleis",
        "entkupplungsgleis_1",
        "rechtsweiche",
        "linksweiche",
        "y_weiche",
        "k84_ausgang",
        "k84_doppelausgang",
        "dreiwegweiche",
        "DKW 2 Antriebe",
        "DKW 1 Antrieb",
        "lichtsignal_HP01",
        "lichtsignal_HP02",
        "lichtsignal_HP012",
        "lichtsignal_HP012_SH01",
        "lichtsignal_SH01",
        "formsignal_HP01",
        "formsignal_HP02",
        "formsignal_HP012",
        "formsignal_HP012_SH01",
        "formsignal_SH01",
        "urc_lichtsignal_HP01",
        "urc_lichtsignal_HP012",
        "urc_lichtsignal_HP012_SH01",
        "urc_lichtsignal_SH01",
        "schiebebuehne",
        "drehscheibe_alt",
        "digitaldrehscheibe",
    };
    ASSERT_EQ(accessoryTypes().size(), documented.size());
    for (std::size_t i = 0; i < documented.size(); ++i)
        EXPECT_EQ(accessoryTypes()[i].key, documented[i]);
    EXPECT_EQ(findAccessoryType("drehscheibe_mfx"), nullptr);
}

TEST(AccessoryType, AddressesAndPositionsOfEachKind) {
    struct Expected {
        std::string_view key;
        int addresses;
        int positions;
    };
    for (const Expected& expected : std::vector<Expected>{{"rechtsweiche", 1, 2},
                                                          {"std_rot_gruen", 1, 2},
                                                          {"lichtsignal_HP01", 1, 2},
                                                          {"std_rot", 1, 1},
                                                          {"entkupplungsgleis", 1, 1},
                                                          {"k84_ausgang", 1, 2},
                                                          {"dreiwegweiche", 2, 3},
                                                          {"formsignal_HP012", 2, 3},
                                                          {"lichtsignal_HP012_SH01", 2, 4},
                                                          {"urc_lichtsignal_HP012_SH01", 2, 4},
                                                          {"DKW 2 Antriebe", 2, 4},
                                                          {"schiebebuehne", 2, 4},
                                                          {"drehscheibe_alt", 2, 4},
                                                          {"digitaldrehscheibe", 16, 32}}) {
        const AccessoryTypeInfo* type = findAccessoryType(expected.key);
        ASSERT_NE(type, nullptr) << expected.key;
        EXPECT_EQ(type->addresses, expected.addresses) << expected.key;
        EXPECT_EQ(type->positions, expected.positions) << expected.key;
    }
    const AccessoryTypeInfo& hp012 = *findAccessoryType("formsignal_HP012");
    EXPECT_TRUE(hp012.acceptsPosition(3));
    EXPECT_FALSE(hp012.acceptsPosition(2));
    EXPECT_TRUE(findAccessoryType("entkupplungsgleis")->singleOutput);
    EXPECT_FALSE(findAccessoryType("rechtsweiche")->singleOutput);
    EXPECT_FALSE(findAccessoryType("rechtsweiche")->acceptsPosition(32));
}

TEST(AccessoryType, EveryCorpusTypeIsKnown) {
    for (std::string_view path : {corpus::magnetartikelTrainControl, corpus::magnetartikelGbert})
        for (const Accessory& accessory : readCorpusFile(path).file.accessories)
            EXPECT_NE(accessory.typeInfo(), nullptr) << path << ": " << accessory.type;
}

TEST(AccessoryFile, DamagedFilesAreReadAndWrittenBack) {
    const std::string originals[] = {readCorpus(corpus::magnetartikelGbert),
                                     readCorpus(corpus::magnetartikelTrainControl)};
    std::mt19937 random(20240531);
    for (int round = 0; round < 2000; ++round) {
        const std::string bytes = damaged(originals[round % 2], random);
        Parsed parsed = parseText(bytes);
        ASSERT_EQ(parsed.document.serialize(), bytes) << "round " << round;
        const AccessoryFile file = AccessoryFile::read(parsed.document, parsed.diagnostics);
        const std::string written = file.write().serialize();
        if (recordsGrouped(parsed.document, AccessoryFile::recordKeyword)) {
            ASSERT_EQ(written, bytes) << "round " << round;
        }
        Diagnostics again;
        AccessoryFile::read(Document::parse(written, again), again);
    }
}

} // namespace
} // namespace stellwerk::cs2config::test
