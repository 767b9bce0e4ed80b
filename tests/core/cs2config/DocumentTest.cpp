// The .cs2 document model: byte-for-byte round trips, one-line edits, and honest diagnostics.

#include "ConfigTestSupport.h"
#include "cs2config/RecordEditor.h"

#include <random>

namespace stellwerk::cs2config::test {
namespace {

const std::vector<std::string_view> everyCorpusCs2File = {
    corpus::gleisbildGbert,
    corpus::karben,
    corpus::gbs0,
    corpus::gleisbildMrFlexi,
    corpus::gleisbildSample,
    corpus::testPage,
    corpus::lokomotiveTrainControl,
    corpus::lokomotiveGbert,
    corpus::lokomotiveSrseii,
    corpus::lokomotiveCorrupted,
    corpus::magnetartikelTrainControl,
    corpus::magnetartikelGbert,
    corpus::fahrstrassen,
    corpus::cs3TrackPlan,
    corpus::cs3Loco,
};

// 8.1: the document's lokomotive.cs2 example.
constexpr std::string_view documentLokomotive = "[lokomotive]\n"
                                                "version\n"
                                                ".major=0\n"
                                                ".minor=3\n"
                                                "session\n"
                                                ".id=24\n"
                                                "lokomotive\n"
                                                ".uid=0xc002\n"
                                                ".name=Dcc-2\n"
                                                ".funktionen\n"
                                                "..nr=0\n"
                                                "..typ=1\n"
                                                "..dauer=0\n"
                                                "..wert=0\n"
                                                ".inTraktion=0xffffffff\n";

TEST(Cs2Document, EveryCorpusFileRoundTripsByteForByte) {
    for (std::string_view file : everyCorpusCs2File) {
        const std::string bytes = readCorpus(file);
        ASSERT_FALSE(bytes.empty()) << file;
        Parsed parsed = parseText(bytes);
        EXPECT_EQ(parsed.document.serialize(), bytes) << file;
        EXPECT_TRUE(parsed.document.isConfiguration()) << file;
    }
}

TEST(Cs2Document, CorpusSectionsAreRead) {
    EXPECT_EQ(parseCorpus(corpus::lokomotiveTrainControl).document.section(), "lokomotive");
    EXPECT_EQ(parseCorpus(corpus::magnetartikelGbert).document.section(), "magnetartikel");
    EXPECT_EQ(parseCorpus(corpus::fahrstrassen).document.section(), "fahrstrassen");
    EXPECT_EQ(parseCorpus(corpus::gleisbildMrFlexi).document.section(), "gleisbild");
    EXPECT_EQ(parseCorpus(corpus::karben).document.section(), "gleisbildseite");
    EXPECT_EQ(parseCorpus(corpus::cs3TrackPlan).document.section(), "conf");
}

TEST(Cs2Document, CleanCorpusFilesHaveNoDiagnostics) {
    for (std::string_view file : {corpus::lokomotiveTrainControl, corpus::magnetartikelTrainControl,
                                  corpus::fahrstrassen, corpus::karben, corpus::testPage}) {
        Parsed parsed = parseCorpus(file);
        EXPECT_TRUE(parsed.diagnostics.empty()) << parsed.diagnostics.formatAll();
    }
}

TEST(Cs2Document, DocumentExampleNestsByDots) {
    Parsed parsed = parseText(documentLokomotive);
    const Document& document = parsed.document;
    ASSERT_EQ(document.records("lokomotive").size(), 1u);
    const Node& loco = *document.record("lokomotive");
    EXPECT_EQ(loco.valueOf("uid"), "0xc002");
    EXPECT_EQ(loco.valueOf("name"), "Dcc-2");
    EXPECT_EQ(loco.valueOf("inTraktion"), "0xffffffff");
    const Node* functions = loco.find("funktionen");
    ASSERT_NE(functions, nullptr);
    EXPECT_FALSE(functions->hasValue());
    EXPECT_EQ(functions->level(), 1);
    EXPECT_EQ(functions->children().size(), 4u);
    EXPECT_EQ(functions->valueOf("typ"), "1");
    EXPECT_EQ(functions->find("typ")->lineNumber(), 12);
    EXPECT_EQ(document.record("session")->valueOf("id"), "24");
    EXPECT_EQ(document.style().indent, "");
}

TEST(Cs2Document, TwoSpaceIndentOfTheRouteExampleIsRead) {
    Parsed parsed = parseText("[fahrstrassen]\nversion\n  .major=0\n  .minor=1\nfahrstrasse\n  .id=1\n"
                              "  .item\n  ..fsverweis=-1\n  ..magnetartikel=23\n  ..stellung=1\n");
    const Node& route = *parsed.document.record("fahrstrasse");
    EXPECT_EQ(route.find("item")->valueOf("magnetartikel"), "23");
    EXPECT_EQ(parsed.document.style().indent, "  ");
    EXPECT_TRUE(parsed.diagnostics.empty());
}

TEST(Cs2Document, EditingOneValueChangesOnlyThatLine) {
    const std::string bytes = readCorpus(corpus::lokomotiveTrainControl);
    Parsed parsed = parseText(bytes);
    Node* loco = parsed.document.records("lokomotive").at(3);
    const std::string oldName(loco->valueOf("name").value());
    loco->find("name")->setValue("Neuer Name");
    const std::string written = parsed.document.serialize();

    std::string expected = bytes;
    const std::string oldLine = " .name=" + oldName + "\n";
    const std::size_t at = expected.find(oldLine, expected.find(loco->find("uid")->raw()) - 200);
    ASSERT_NE(at, std::string::npos);
    expected.replace(at, oldLine.size(), " .name=Neuer Name\n");
    EXPECT_EQ(written, expected);
}

TEST(Cs2Document, EditedValueOnALatin1LineIsWrittenAsUtf8) {
    Parsed parsed = parseText("[lokomotive]\nlokomotive\n .name=Gl\xE4serzug\n .uid=0x5\n");
    ASSERT_EQ(parsed.diagnostics.items().size(), 1u);
    EXPECT_EQ(parsed.diagnostics.items()[0].line, 3);
    EXPECT_EQ(parsed.diagnostics.items()[0].message, "not valid UTF-8");
    Node& loco = *parsed.document.record("lokomotive");
    EXPECT_EQ(loco.valueOf("name"), "Gl\xC3\xA4serzug");
    EXPECT_EQ(parsed.document.serialize(), "[lokomotive]\nlokomotive\n .name=Gl\xE4serzug\n .uid=0x5\n");
    loco.find("name")->setValue("Glaskasten");
    EXPECT_EQ(parsed.document.serialize(), "[lokomotive]\nlokomotive\n .name=Glaskasten\n .uid=0x5\n");
}

TEST(Cs2Document, CorruptedHeaderLineIsReportedAndKept) {
    Parsed parsed = parseCorpus(corpus::lokomotiveCorrupted);
    ASSERT_FALSE(parsed.diagnostics.empty());
    const Diagnostic& first = parsed.diagnostics.items().front();
    EXPECT_EQ(first.line, 7);
    EXPECT_EQ(first.message, "unreadable line ' komotive]' (a damaged section header?)");
    EXPECT_EQ(first.action, "kept unchanged and not read");
    EXPECT_EQ(parsed.diagnostics.format(first), "lokomotive.cs2:7: warning: unreadable line ' komotive]' "
                                                "(a damaged section header?); kept unchanged and not read");
    EXPECT_FALSE(parsed.diagnostics.hasErrors());
    EXPECT_GE(parsed.document.records("lokomotive").size(), 2u);
}

TEST(Cs2Document, JunkBeforeTheHeaderIsKeptAndReported) {
    const std::string bytes = "garbage from a download\n\x01\x02\n[magnetartikel]\nartikel\n .id=1\n";
    Parsed parsed = parseText(bytes);
    EXPECT_EQ(parsed.document.section(), "magnetartikel");
    EXPECT_EQ(parsed.document.records("artikel").size(), 1u);
    EXPECT_EQ(parsed.document.records("garbage").size(), 0u);
    ASSERT_EQ(parsed.diagnostics.items().size(), 1u);
    EXPECT_EQ(parsed.diagnostics.items()[0].message, "2 line(s) before the [section] header");
    EXPECT_EQ(parsed.document.serialize(), bytes);
}

TEST(Cs2Document, HeaderWithJunkInFrontOnTheSameLineIsRecognisedAndKept) {
    const std::string bytes = "Bau [magnetartikel]\nartikel\n .id=1\n .name=W1\n";
    Parsed parsed = parseText(bytes, "magnetartikel.cs2");
    EXPECT_TRUE(parsed.document.hasHeader());
    EXPECT_EQ(parsed.document.section(), "magnetartikel");
    EXPECT_EQ(parsed.document.records("artikel").size(), 1u);
    EXPECT_EQ(parsed.document.records("Bau").size(), 0u);
    ASSERT_EQ(parsed.diagnostics.items().size(), 1u) << parsed.diagnostics.formatAll();
    EXPECT_EQ(parsed.diagnostics.format(parsed.diagnostics.items()[0]),
              "magnetartikel.cs2:1: warning: 'Bau ' in front of the section header [magnetartikel]; read as "
              "the header; the text in front of it is kept unchanged");
    EXPECT_EQ(parsed.document.serialize(), bytes);
}

TEST(Cs2Document, ByteOrderMarkAndJunkLinesBeforeAJunkHeaderAreKept) {
    const std::string bytes = "saved by tool\r\n\xEF\xBB\xBF[lokomotive]\r\nlokomotive\r\n .name=V 100\r\n";
    Parsed parsed = parseText(bytes);
    EXPECT_EQ(parsed.document.section(), "lokomotive");
    EXPECT_EQ(parsed.document.style().newline, "\r\n");
    ASSERT_EQ(parsed.document.records("lokomotive").size(), 1u);
    EXPECT_EQ(parsed.document.records("lokomotive")[0]->valueOf("name"), "V 100");
    ASSERT_EQ(parsed.diagnostics.items().size(), 2u) << parsed.diagnostics.formatAll();
    EXPECT_EQ(parsed.diagnostics.items()[0].message, "1 line(s) before the [section] header");
    EXPECT_EQ(parsed.diagnostics.items()[1].line, 2);
    EXPECT_EQ(parsed.document.serialize(), bytes);
}

TEST(Cs2Document, AValueEndingInBracketsIsNotAHeader) {
    Parsed parsed = parseText("lokomotive\n .name=Gleis [3]\n");
    EXPECT_FALSE(parsed.document.hasHeader());
    EXPECT_EQ(parsed.document.record("lokomotive")->valueOf("name"), "Gleis [3]");
}

TEST(Cs2Document, ACleanHeaderWinsOverALineThatEndsInBrackets) {
    Parsed parsed = parseText("Bau [magnetartikel]\n[lokomotive]\nlokomotive\n");
    EXPECT_EQ(parsed.document.section(), "lokomotive");
    EXPECT_EQ(parsed.document.serialize(), "Bau [magnetartikel]\n[lokomotive]\nlokomotive\n");
}

TEST(Cs2Document, MissingFinalNewlineAndCrLfSurvive) {
    for (std::string_view bytes : {std::string_view("[gleisbildseite]\nelement\n .id=0x1\n .typ=gerade"),
                                   std::string_view("[gleisbildseite]\r\nelement\r\n .id=0x1\r\n"),
                                   std::string_view("[gleisbildseite]\r\nelement\n .id=0x1\r\n")}) {
        Parsed parsed = parseText(bytes);
        EXPECT_EQ(parsed.document.serialize(), bytes);
        EXPECT_EQ(parsed.document.record("element")->valueOf("id"), "0x1");
        EXPECT_TRUE(parsed.diagnostics.empty()) << parsed.diagnostics.formatAll();
    }
    EXPECT_EQ(parseText("[a]\r\nb\r\n").document.style().newline, "\r\n");
}

TEST(Cs2Document, TruncatedFileKeepsWhatWasThere) {
    const std::string bytes = readCorpus(corpus::lokomotiveGbert).substr(0, 5000);
    Parsed parsed = parseText(bytes);
    EXPECT_EQ(parsed.document.serialize(), bytes);
    EXPECT_GT(parsed.document.records("lokomotive").size(), 1u);
}

TEST(Cs2Document, BrokenLinesAreReportedWithTheirLineNumbers) {
    Parsed parsed = parseText("[lokomotive]\nlokomotive\n .name=A\n=oops\n .uid 0x5\n ..\n .uid=0x5\n");
    ASSERT_EQ(parsed.diagnostics.items().size(), 3u);
    EXPECT_EQ(parsed.diagnostics.items()[0].line, 4);
    EXPECT_EQ(parsed.diagnostics.items()[1].line, 5);
    EXPECT_EQ(parsed.diagnostics.items()[2].line, 6);
    EXPECT_EQ(parsed.document.record("lokomotive")->valueOf("uid"), "0x5");
}

TEST(Cs2Document, NestedLineWithoutItsBlockIsReported) {
    Parsed parsed = parseText("[lokomotive]\nlokomotive\n..nr=3\n");
    ASSERT_EQ(parsed.diagnostics.items().size(), 1u);
    EXPECT_EQ(parsed.diagnostics.items()[0].line, 3);
    EXPECT_EQ(parsed.document.record("lokomotive")->valueOf("nr"), "3");
}

TEST(Cs2Document, SecondHeaderIsReported) {
    Parsed parsed = parseText("[lokomotive]\nlokomotive\n .uid=1\n[lokomotive]\nlokomotive\n .uid=2\n");
    ASSERT_EQ(parsed.diagnostics.items().size(), 1u);
    EXPECT_EQ(parsed.diagnostics.items()[0].line, 4);
    EXPECT_EQ(parsed.document.records("lokomotive").size(), 2u);
}

TEST(Cs2Document, HeaderlessStreamIsReadWithAWarning) {
    // 8.8: ldbver has no header; the MS2 pads its lines with spaces.
    Parsed parsed = parseText(".version=9  \n.monat=2  \n.jahr=10  \n.anzahl=1078");
    EXPECT_TRUE(parsed.document.isConfiguration());
    EXPECT_FALSE(parsed.document.hasHeader());
    EXPECT_FALSE(parsed.diagnostics.hasErrors());
    EXPECT_EQ(parsed.document.root().valueOf("anzahl"), "1078");
    EXPECT_EQ(parsed.document.root().valueOf("version"), "9  ");
}

TEST(Cs2Document, BinaryDataIsNotAConfigurationFile) {
    std::string png = "\x89PNG\r\n\x1A\n";
    png += std::string("\0\0\0\rIHDR\0\0\x01\0", 13);
    Parsed parsed = parseText(png, "icon.png");
    EXPECT_FALSE(parsed.document.isConfiguration());
    EXPECT_TRUE(parsed.diagnostics.hasErrors());
    EXPECT_EQ(parsed.document.serialize(), png);
    EXPECT_FALSE(parseText("").document.isConfiguration());
}

TEST(Cs2Document, TooDeepNestingIsKeptVerbatim) {
    const std::string deep = "[x]\nr\n" + std::string(Document::maxLevel + 1, '.') + "k=1\n";
    Parsed parsed = parseText(deep);
    ASSERT_EQ(parsed.diagnostics.items().size(), 1u);
    EXPECT_EQ(parsed.diagnostics.items()[0].line, 3);
    EXPECT_EQ(parsed.document.serialize(), deep);
}

TEST(Cs2Document, DiagnosticsAreBounded) {
    std::string junk = "[lokomotive]\n";
    for (int i = 0; i < 10000; ++i)
        junk += "?!\n";
    Parsed parsed = parseText(junk);
    EXPECT_EQ(parsed.diagnostics.items().size(), Diagnostics::defaultLimit);
    EXPECT_EQ(parsed.diagnostics.count(), 10000u);
    EXPECT_NE(parsed.diagnostics.formatAll().find("9500 more problems not listed"), std::string::npos);
}

TEST(Cs2Document, AnyBytesRoundTrip) {
    std::mt19937 random(20261121);
    const std::string seed = readCorpus(corpus::lokomotiveSrseii);
    for (int round = 0; round < 2000; ++round) {
        std::string bytes = seed.substr(0, random() % seed.size());
        for (int flips = static_cast<int>(random() % 20); flips > 0 && !bytes.empty(); --flips)
            bytes[random() % bytes.size()] = static_cast<char>(random() % 256);
        Parsed parsed = parseText(bytes);
        ASSERT_EQ(parsed.document.serialize(), bytes) << "round " << round;
    }
}

TEST(Cs2Document, RecordEditorKeepsEquivalentNumbersAndAddsMissingKeys) {
    Parsed parsed = parseText("[lokomotive]\nlokomotive\n .uid=0x0005\n .name=A\n .funktionen\n ..nr=0\n");
    Node& loco = *parsed.document.record("lokomotive");
    RecordEditor editor(loco, parsed.document.style());
    editor.setInteger("uid", 5, RecordEditor::Base::Hex);
    editor.setInteger("vmax", 255, RecordEditor::Base::Decimal, 255);
    editor.setOptionalText("icon", "");
    EXPECT_EQ(parsed.document.serialize(),
              "[lokomotive]\nlokomotive\n .uid=0x0005\n .name=A\n .funktionen\n ..nr=0\n");
    editor.setInteger("uid", 6, RecordEditor::Base::Hex);
    editor.setInteger("av", 30);
    editor.setText("name", "B");
    EXPECT_EQ(parsed.document.serialize(),
              "[lokomotive]\nlokomotive\n .uid=0x6\n .name=B\n .av=30\n .funktionen\n ..nr=0\n");
    editor.remove("av");
    Node& block = editor.appendBlock("funktionen");
    RecordEditor(block, parsed.document.style()).setInteger("nr", 1);
    EXPECT_EQ(
        parsed.document.serialize(),
        "[lokomotive]\nlokomotive\n .uid=0x6\n .name=B\n .funktionen\n ..nr=0\n .funktionen\n ..nr=1\n");
}

TEST(Cs2Document, LinesAddedAtTheEndOfAFileWithoutFinalNewline) {
    Parsed parsed = parseText("[lokomotive]\nlokomotive\n .name=A");
    RecordEditor editor(*parsed.document.record("lokomotive"), parsed.document.style());
    editor.setText("uid", "0x1");
    EXPECT_EQ(parsed.document.serialize(), "[lokomotive]\nlokomotive\n .name=A\n .uid=0x1");
    editor.appendBlock("funktionen");
    EXPECT_EQ(parsed.document.serialize(), "[lokomotive]\nlokomotive\n .name=A\n .uid=0x1\n .funktionen");
}

TEST(Cs2Document, ReplaceRecordsKeepsOtherRecordsInPlace) {
    Parsed parsed =
        parseText("[magnetartikel]\nversion\n .minor=1\nartikel\n .id=1\nartikel\n .id=2\nfoo\n .x=1");
    Document& document = parsed.document;
    std::vector<Node> articles;
    articles.push_back(*document.records("artikel").at(1));
    Node added = document.newRecord("artikel");
    RecordEditor(added, document.style()).setInteger("id", 3);
    articles.push_back(added);
    document.replaceRecords("artikel", std::move(articles));
    EXPECT_EQ(document.serialize(),
              "[magnetartikel]\nversion\n .minor=1\nartikel\n .id=2\nartikel\n .id=3\nfoo\n .x=1");
    std::vector<Node> more;
    Node gleis = document.newRecord("gleis");
    more.push_back(gleis);
    document.replaceRecords("gleis", std::move(more));
    EXPECT_EQ(document.serialize(),
              "[magnetartikel]\nversion\n .minor=1\nartikel\n .id=2\nartikel\n .id=3\nfoo\n .x=1\ngleis");
}

TEST(Cs2Document, ReplaceRecordsKeepsInterleavedRecordsWhereTheyWere) {
    Parsed parsed = parseText("[x]\nartikel\n .id=1\nfoo\nartikel\n .id=2\nbar\n");
    Document& document = parsed.document;
    std::vector<Node> same;
    for (const Node* record : document.records("artikel"))
        same.push_back(*record);
    document.replaceRecords("artikel", same);
    EXPECT_EQ(document.serialize(), "[x]\nartikel\n .id=1\nfoo\nartikel\n .id=2\nbar\n");
    same.push_back(document.newRecord("artikel"));
    document.replaceRecords("artikel", same);
    EXPECT_EQ(document.serialize(), "[x]\nartikel\n .id=1\nfoo\nartikel\n .id=2\nartikel\nbar\n");
    document.replaceRecords("artikel", {same[1]});
    EXPECT_EQ(document.serialize(), "[x]\nartikel\n .id=2\nfoo\nbar\n");
}

TEST(Cs2Document, CreateWritesAHeader) {
    Document document = Document::create("fahrstrassen");
    EXPECT_EQ(document.section(), "fahrstrassen");
    EXPECT_EQ(document.serialize(), "[fahrstrassen]\n");
}

} // namespace
} // namespace stellwerk::cs2config::test
