// magnetartikel.cs2 as typed accessories: the document's example, the two corpus files, writing back byte for
// byte, edits that change only what they change, and the JSON of `stellwerk-cli cs2 json`.

#include "cs2config/AccessoryFile.h"

#include "AccessoryFileTestSupport.h"
#include "ConfigTestSupport.h"

#include <map>
#include <string>

namespace stellwerk::cs2config::test {
namespace {

using namespace accessoryfile;

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

} // namespace
} // namespace stellwerk::cs2config::test
