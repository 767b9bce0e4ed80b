// What reading magnetartikel.cs2 reports: unknown types and keys (once), values that are not numbers,
// duplicate ids, overlapping addresses, positions a type does not have; damaged files still read and write
// back.

#include "AccessoryFileTestSupport.h"
#include "ConfigTestSupport.h"
#include "cs2config/AccessoryAddressCheck.h"
#include "cs2config/AccessoryFile.h"

#include <random>
#include <string>

namespace stellwerk::cs2config::test {
namespace {

using namespace accessoryfile;

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
