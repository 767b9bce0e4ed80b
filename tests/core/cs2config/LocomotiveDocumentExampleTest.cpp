// The examples of the document's chapter 8.1 (lokomotive.cs2), one test per documented section.
#include "ConfigTestSupport.h"
#include "cs2config/LocomotiveFile.h"

#include <gtest/gtest.h>
#include <string>

namespace stellwerk::cs2config::test {
namespace {

// 8.1 "Grundformat", as printed (no indent before the dots).
constexpr std::string_view basicFormat = "[lokomotive]\n"
                                         "version\n"
                                         ".major=0\n"
                                         ".minor=3\n"
                                         "session\n"
                                         ".id=24\n"
                                         "lokomotive\n"
                                         ".uid=0xc002\n"
                                         ".name=Dcc-2\n"
                                         ".vorname=Dcc-2\n"
                                         ".adresse=0x3e8\n"
                                         ".typ=dcc\n"
                                         ".sid=0xcdcd\n"
                                         ".mfxuid=0xffffffff\n"
                                         ".icon=\n"
                                         ".symbol=0\n"
                                         ".av=30\n"
                                         ".bv=30\n"
                                         ".volume=2\n"
                                         ".progmask=0x2\n"
                                         ".velocity=0\n"
                                         ".richtung=0\n"
                                         ".tachomax=350\n"
                                         ".vmax=255\n"
                                         ".vmin=1\n"
                                         ".xprot=3\n"
                                         ".mfxtyp=205\n"
                                         ".funktionen\n"
                                         "..nr=0\n"
                                         "..typ=1\n"
                                         "..dauer=0\n"
                                         "..wert=0\n"
                                         ".inTraktion=0xffffffff\n";

using ReadText = ReadModel<LocomotiveFile>;

ReadText readExampleText(std::string_view text) {
    return readAs<LocomotiveFile>(text, "lokomotive.cs2");
}

// A record of the basic format with the given lines in place of its functions.
std::string withBlock(std::string_view block) {
    std::string text(basicFormat);
    const std::size_t at = text.find(".funktionen\n");
    text.replace(at, text.find(".inTraktion") - at, block);
    return text;
}

TEST(LocomotiveDocumentExample, BasicFormatReadsEveryField) {
    const ReadText read = readExampleText(basicFormat);
    EXPECT_TRUE(read.diagnostics.empty()) << read.diagnostics.formatAll();
    ASSERT_EQ(read.file.locomotives.size(), 1u);
    const Locomotive& locomotive = read.file.locomotives.front();
    EXPECT_EQ(locomotive.uid, 0xc002u);
    EXPECT_EQ(locomotive.name, "Dcc-2");
    EXPECT_EQ(locomotive.previousName, "Dcc-2");
    EXPECT_EQ(locomotive.address, 1000u);
    EXPECT_EQ(locomotive.decoder, LocomotiveDecoder::Dcc);
    EXPECT_EQ(locomotive.sid, 0xcdcdu);
    EXPECT_EQ(locomotive.mfxUid, 0xffffffffu);
    EXPECT_EQ(locomotive.icon, "");
    EXPECT_EQ(locomotive.symbol, 0);
    EXPECT_EQ(locomotive.acceleration, 30);
    EXPECT_EQ(locomotive.braking, 30);
    EXPECT_EQ(locomotive.volume, 2);
    EXPECT_EQ(locomotive.programmingMask, 2);
    EXPECT_EQ(locomotive.velocity, 0);
    EXPECT_EQ(locomotive.direction, TravelDirection::Forward);
    EXPECT_EQ(locomotive.tachoMax, 350);
    EXPECT_EQ(locomotive.vMax, 255);
    EXPECT_EQ(locomotive.vMin, 1);
    EXPECT_EQ(locomotive.extendedProtocol, 3);
    EXPECT_EQ(locomotive.mfxType, 205);
    EXPECT_EQ(locomotive.inTraction, Locomotive::noTraction);
    ASSERT_EQ(locomotive.functions.size(), 1u);
    EXPECT_EQ(locomotive.functions[0].number, 0);
    EXPECT_EQ(locomotive.functions[0].icon, 1);
    EXPECT_EQ(locomotive.functions[0].trigger(), FunctionTrigger::Latching);
    EXPECT_EQ(locomotive.functions[0].value, 0);
}

TEST(LocomotiveDocumentExample, BasicFormatWritesBackUnchanged) {
    const ReadText read = readExampleText(basicFormat);
    EXPECT_EQ(read.file.write().serialize(), basicFormat);
}

// 8.1.1: "version" with .major and .minor; current values 0 and 3; only once in a file.
TEST(LocomotiveDocumentExample, VersionSection) {
    const ReadText read = readExampleText(basicFormat);
    ASSERT_TRUE(read.file.version);
    EXPECT_EQ(read.file.version->major, 0);
    EXPECT_EQ(read.file.version->minor, 3);
}

TEST(LocomotiveDocumentExample, VersionSectionOnlyOnce) {
    std::string text(basicFormat);
    text += "version\n.major=1\n.minor=0\n";
    const ReadText read = readExampleText(text);
    ASSERT_EQ(read.diagnostics.items().size(), 1u) << read.diagnostics.formatAll();
    EXPECT_EQ(read.diagnostics.items()[0].line, 34);
    EXPECT_EQ(read.diagnostics.items()[0].message,
              "second 'version' record (lines 2 and 34); the file has one");
    EXPECT_EQ(read.file.version->major, 0);
}

// 8.1.2: "session" .id, the mfx registration counter.
TEST(LocomotiveDocumentExample, SessionSection) {
    ReadText read = readExampleText(basicFormat);
    EXPECT_EQ(read.file.session, 24);
    read.file.session = 25;
    EXPECT_NE(read.file.write().serialize().find("session\n.id=25\n"), std::string::npos);
}

// 8.1.3.1: ..nr 0 -> F0 .. 15 -> F15, ..typ icon, ..dauer 0 latching / -1 momentary / else timed.
TEST(LocomotiveDocumentExample, FunctionsSection) {
    const ReadText read = readExampleText(withBlock(".funktionen\n..nr=0\n..typ=1\n..dauer=0\n..wert=1\n"
                                                    ".funktionen\n..nr=1\n..typ=7\n..dauer=-1\n..wert=0\n"
                                                    ".funktionen\n..nr=15\n..typ=18\n..dauer=5\n..wert=0\n"));
    EXPECT_TRUE(read.diagnostics.empty()) << read.diagnostics.formatAll();
    const Locomotive& locomotive = read.file.locomotives.front();
    ASSERT_EQ(locomotive.functions.size(), 3u);
    EXPECT_EQ(locomotive.function(0)->trigger(), FunctionTrigger::Latching);
    EXPECT_EQ(locomotive.function(0)->value, 1);
    EXPECT_EQ(locomotive.function(1)->trigger(), FunctionTrigger::Momentary);
    EXPECT_EQ(locomotive.function(1)->icon, 7);
    EXPECT_EQ(locomotive.function(15)->trigger(), FunctionTrigger::Timed);
    EXPECT_EQ(locomotive.function(15)->timedValue(), 5);
}

TEST(LocomotiveDocumentExample, FunctionTriggerIsWrittenAsDauer) {
    ReadText read = readExampleText(basicFormat);
    Function& f0 = read.file.locomotives.front().functions.front();
    f0.setTrigger(FunctionTrigger::Momentary);
    EXPECT_NE(read.file.write().serialize().find("..dauer=-1\n"), std::string::npos);
    f0.setTrigger(FunctionTrigger::Timed, 3);
    EXPECT_NE(read.file.write().serialize().find("..dauer=3\n"), std::string::npos);
}

// 8.1.3.2: ".prg": one row of the extended CV programming dialog.
TEST(LocomotiveDocumentExample, ProgrammingSection) {
    const ReadText read =
        readExampleText(withBlock(".prg\n..adresse=1\n..name=Cv Name\n..wert=3\n..maske=0\n"));
    EXPECT_TRUE(read.diagnostics.empty()) << read.diagnostics.formatAll();
    const Locomotive& locomotive = read.file.locomotives.front();
    ASSERT_EQ(locomotive.cvRows.size(), 1u);
    EXPECT_EQ(locomotive.cvRows[0].cv, 1);
    EXPECT_EQ(locomotive.cvRows[0].name, "Cv Name");
    EXPECT_EQ(locomotive.cvRows[0].value, 3);
    EXPECT_EQ(locomotive.cvRows[0].mask, 0);
}

// 8.1.3: the decoder types the document lists, and those real files use.
TEST(LocomotiveDocumentExample, DecoderTypes) {
    for (const std::string_view type : {"mm2_prg", "mm2_dil8", "dcc", "mfx", "sx1", "mm_prg", "mmm2_lok"}) {
        std::string text(basicFormat);
        text.replace(text.find(".typ=dcc"), 8, ".typ=" + std::string(type));
        const ReadText read = readExampleText(text);
        EXPECT_TRUE(read.diagnostics.empty()) << type << ": " << read.diagnostics.formatAll();
        EXPECT_EQ(read.file.locomotives.front().decoderTypeText(), type);
        EXPECT_NE(read.file.locomotives.front().decoder, LocomotiveDecoder::Unknown);
    }
}

TEST(LocomotiveDocumentExample, UnknownDecoderTypeIsKeptAndReportedOnce) {
    std::string text(basicFormat);
    text.replace(text.find(".typ=dcc"), 8, ".typ=mfx+");
    text += "lokomotive\n.uid=0xc003\n.name=Dcc-3\n.adresse=0x3\n.typ=mfx+\n";
    ReadText read = readExampleText(text);
    ASSERT_EQ(read.diagnostics.items().size(), 1u) << read.diagnostics.formatAll();
    EXPECT_EQ(read.diagnostics.items()[0].line, 12);
    EXPECT_EQ(read.diagnostics.items()[0].message, "unknown decoder type 'mfx+' (2 times, first here)");
    EXPECT_EQ(read.file.locomotives.front().decoder, LocomotiveDecoder::Unknown);
    EXPECT_EQ(read.file.locomotives.front().decoderTypeText(), "mfx+");
    EXPECT_EQ(read.file.write().serialize(), text);
}

TEST(LocomotiveDocumentExample, ValuesThatAreNotNumbersAreKeptAndReported) {
    std::string text(basicFormat);
    text.replace(text.find(".av=30"), 6, ".av=fast");
    ReadText read = readExampleText(text);
    ASSERT_EQ(read.diagnostics.items().size(), 1u) << read.diagnostics.formatAll();
    EXPECT_EQ(read.diagnostics.items()[0].line, 17);
    EXPECT_EQ(read.diagnostics.items()[0].message, "'.av' is not a number: 'fast'");
    EXPECT_EQ(read.diagnostics.items()[0].action, "kept unchanged; read as 0");
    EXPECT_EQ(read.file.locomotives.front().acceleration, 0);
    EXPECT_EQ(read.file.write().serialize(), text);
    read.file.locomotives.front().acceleration = 12;
    EXPECT_NE(read.file.write().serialize().find("\n.av=12\n"), std::string::npos);
}

TEST(LocomotiveDocumentExample, RecordWithoutRequiredKeysIsReported) {
    std::string text(basicFormat);
    text += "lokomotive\n.name=Nameless\n.typ=mm2_prg\n";
    const ReadText read = readExampleText(text);
    ASSERT_EQ(read.diagnostics.items().size(), 2u) << read.diagnostics.formatAll();
    EXPECT_EQ(read.diagnostics.items()[0].message, "locomotive record without '.uid'");
    EXPECT_EQ(read.diagnostics.items()[1].message, "locomotive record without '.adresse'");
    EXPECT_EQ(read.diagnostics.items()[1].line, 34);
}

TEST(LocomotiveDocumentExample, KeyTwiceInARecordUsesTheFirst) {
    std::string text(basicFormat);
    text.replace(text.find(".vmin=1\n"), 8, ".vmin=1\n.vmin=7\n");
    const ReadText read = readExampleText(text);
    ASSERT_EQ(read.diagnostics.items().size(), 1u) << read.diagnostics.formatAll();
    EXPECT_EQ(read.diagnostics.items()[0].message,
              "'.vmin' appears twice in a locomotive record (lines 25 and 26)");
    EXPECT_EQ(read.file.locomotives.front().vMin, 1);
}

TEST(LocomotiveDocumentExample, FunctionProblemsAreReported) {
    const ReadText read =
        readExampleText(withBlock(".funktionen\n..nr=3\n.funktionen\n..nr=3\n.funktionen\n..typ=4\n"
                                  ".funktionen\n..nr=40\n.funktionen_2\n..nr=2\n"));
    const auto& items = read.diagnostics.items();
    ASSERT_EQ(items.size(), 4u) << read.diagnostics.formatAll();
    EXPECT_EQ(items[0].message, "F3 appears twice in locomotive 'Dcc-2' (lines 28 and 30)");
    EXPECT_EQ(items[1].message, "function F40 of locomotive 'Dcc-2' is outside F0-F31");
    EXPECT_EQ(items[2].message, "F2 is in a '.funktionen_2' block, which holds F16-F31");
    EXPECT_EQ(items[3].message, "function block without '..nr'");
    EXPECT_EQ(items[3].line, 32);
}

TEST(LocomotiveDocumentExample, TractionToAMissingUnitIsReported) {
    std::string text(basicFormat);
    text.replace(text.find(".inTraktion=0xffffffff"), 22, ".inTraktion=0x2c01");
    const ReadText read = readExampleText(text);
    ASSERT_EQ(read.diagnostics.items().size(), 1u) << read.diagnostics.formatAll();
    EXPECT_EQ(read.diagnostics.items()[0].message,
              "locomotive 'Dcc-2' runs in unit 0x2c01, which is not in this file");
    EXPECT_EQ(read.diagnostics.items()[0].line, 33);
}

// A file made from nothing: the records the document shows, in its order and the CS2's indent.
TEST(LocomotiveDocumentExample, NewFileIsWrittenInTheDocumentsOrder) {
    LocomotiveFile file;
    file.version = LocomotiveFile::Version{};
    file.session = 24;
    Locomotive locomotive;
    locomotive.uid = 0xc002;
    locomotive.name = "Dcc-2";
    locomotive.address = 0x3e8;
    locomotive.decoder = LocomotiveDecoder::Dcc;
    locomotive.acceleration = 30;
    locomotive.tachoMax = 350;
    locomotive.functions.push_back(Function{0, 1, 0, 0, {}});
    file.locomotives.push_back(locomotive);
    const std::string written = file.write().serialize();
    EXPECT_EQ(written, "[lokomotive]\n"
                       "version\n .major=0\n .minor=3\n"
                       "session\n .id=24\n"
                       "lokomotive\n .uid=0xc002\n .name=Dcc-2\n .adresse=0x3e8\n .typ=dcc\n .av=30\n"
                       " .tachomax=350\n .funktionen\n ..nr=0\n ..typ=1\n");
    Diagnostics diagnostics;
    const LocomotiveFile again = LocomotiveFile::read(Document::parse(written, diagnostics), diagnostics);
    EXPECT_TRUE(diagnostics.empty()) << diagnostics.formatAll();
    EXPECT_EQ(again.locomotives.front().name, "Dcc-2");
    EXPECT_EQ(again.locomotives.front().address, 1000u);
}

} // namespace
} // namespace stellwerk::cs2config::test
