#include "cs2config/TrackPage.h"

#include "ConfigTestSupport.h"

#include <gtest/gtest.h>
#include <map>
#include <tuple>

using namespace stellwerk::cs2config;
using namespace stellwerk::cs2config::test;

namespace {

struct ReadPage {
    Diagnostics diagnostics;
    TrackPage page;
};

ReadPage readPageText(std::string_view text) {
    Parsed parsed = parseText(text, "page.cs2");
    TrackPage page = TrackPage::read(parsed.document, parsed.diagnostics);
    return {std::move(parsed.diagnostics), std::move(page)};
}

ReadPage readCorpusPage(std::string_view file) {
    return readPageText(readCorpus(file));
}

std::vector<std::string> splitLines(std::string_view text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = text.find('\n', start);
        lines.emplace_back(
            text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
        if (end == std::string_view::npos)
            break;
        start = end + 1;
    }
    return lines;
}

// The lines of `after` that differ from `before`; both must have the same number of lines.
std::vector<std::string> changedPageLines(std::string_view before, std::string_view after) {
    const std::vector<std::string> a = splitLines(before);
    const std::vector<std::string> b = splitLines(after);
    EXPECT_EQ(a.size(), b.size());
    std::vector<std::string> changed;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
        if (a[i] != b[i])
            changed.push_back(b[i]);
    return changed;
}

auto typedElement(const TrackElement& e) {
    return std::make_tuple(e.position.toId(), e.type, e.rotation, e.article, e.text, e.deviceId, e.state);
}

void expectSameElements(const std::vector<TrackElement>& actual, const std::vector<TrackElement>& expected) {
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < actual.size(); ++i)
        EXPECT_EQ(typedElement(actual[i]), typedElement(expected[i])) << "element " << i;
}

const TrackElement& tileAt(const TrackPage& page, std::uint32_t id) {
    for (const TrackElement& element : page.elements)
        if (element.position.toId() == id)
            return element;
    ADD_FAILURE() << "no element at " << std::hex << id;
    return page.elements.front();
}

std::map<std::string, int> typeCounts(const TrackPage& page) {
    std::map<std::string, int> counts;
    for (const TrackElement& element : page.elements)
        ++counts[element.type];
    return counts;
}

std::vector<std::string> pageMessages(const Diagnostics& diagnostics) {
    std::vector<std::string> texts;
    for (const Diagnostic& diagnostic : diagnostics.items())
        texts.push_back(diagnostics.format(diagnostic));
    return texts;
}

TrackElement element(std::uint32_t id, std::string type, std::int64_t article = -1) {
    TrackElement made;
    made.position = *TrackPosition::fromId(id);
    made.type = std::move(type);
    made.article = article;
    return made;
}

} // namespace

TEST(TrackPage, KarbenCorpusPage) {
    const auto [diagnostics, page] = readCorpusPage(corpus::karben);
    EXPECT_TRUE(diagnostics.empty()) << diagnostics.formatAll();
    EXPECT_EQ(page.format, TrackPlanFormat::Cs2Grid);
    EXPECT_EQ(page.version, (TrackFileVersion{1, 0}));
    ASSERT_EQ(page.elements.size(), 37u);
    EXPECT_EQ(typeCounts(page), (std::map<std::string, int>{{"bogen", 6},
                                                            {"gerade", 15},
                                                            {"linksweiche", 3},
                                                            {"rechtsweiche", 3},
                                                            {"s88kontakt", 3},
                                                            {"signal_p_hp012s", 7}}));
    const TrackElement& turnout = tileAt(page, 0x105);
    EXPECT_EQ(turnout.type, "rechtsweiche");
    EXPECT_EQ(turnout.category(), TrackCategory::Turnout);
    EXPECT_TRUE(turnout.switchable());
    EXPECT_EQ(turnout.rotation, 3);
    EXPECT_EQ(turnout.article, 2);
    EXPECT_EQ(turnout.text, "23");
    EXPECT_EQ(turnout.state, 1);
    const TrackElement& contact = tileAt(page, 0x107);
    EXPECT_EQ(contact.category(), TrackCategory::Feedback);
    EXPECT_EQ(contact.articleLink(), ArticleLink::FeedbackContact);
    EXPECT_EQ(contact.article, 101);
    EXPECT_EQ(contact.deviceId, 0x100);
    EXPECT_EQ(contact.text, "603");
    const TrackElement& track = tileAt(page, 0x103);
    EXPECT_FALSE(track.switchable());
    EXPECT_FALSE(track.hasArticle());
    EXPECT_EQ(track.rotation, 0);
}

// Field notes: drawn the real way (row = bits 8-15) karben.cs2 is a station 14 tiles wide and 4 high.
TEST(TrackPage, KarbenIsFourteenWideAndFourHigh) {
    const auto [diagnostics, page] = readCorpusPage(corpus::karben);
    const std::optional<TrackArea> area = page.area();
    ASSERT_TRUE(area);
    EXPECT_EQ(area->left, 1);
    EXPECT_EQ(area->top, 1);
    EXPECT_EQ(area->right, 13);
    EXPECT_EQ(area->bottom, 3);
    EXPECT_EQ(area->columns(), 14);
    EXPECT_EQ(area->rows(), 4);
}

TEST(TrackPage, CanStreamPageGbs0) {
    const auto [diagnostics, page] = readCorpusPage(corpus::gbs0);
    EXPECT_TRUE(diagnostics.empty()) << diagnostics.formatAll();
    ASSERT_EQ(page.elements.size(), 144u);
    EXPECT_EQ(typeCounts(page), (std::map<std::string, int>{{"s88kontakt", 144}}));
    std::map<std::int64_t, int> devices;
    for (const TrackElement& element : page.elements) {
        ++devices[element.deviceId];
        EXPECT_EQ(element.articleLink(), ArticleLink::FeedbackContact);
    }
    // All on feedback device 0x100 except contact 1001 at 0xa01, which is on device 0x6.
    EXPECT_EQ(devices, (std::map<std::int64_t, int>{{0x6, 1}, {0x100, 143}}));
    EXPECT_EQ(tileAt(page, 0xa01).article, 1001);
    EXPECT_EQ(tileAt(page, 0xa01).deviceId, 0x6);
    EXPECT_EQ(page.elements.front().article, 101);
    EXPECT_EQ(page.area()->columns(), 17);
    EXPECT_EQ(page.area()->rows(), 15);
}

TEST(TrackPage, TrainControlTestPage) {
    const auto [diagnostics, page] = readCorpusPage(corpus::testPage);
    ASSERT_EQ(page.elements.size(), 101u);
    // Every element of this file has an `.id`; one has no `.typ` and is a label.
    std::vector<const TrackElement*> labels;
    for (const TrackElement& element : page.elements)
        if (element.type.empty())
            labels.push_back(&element);
    ASSERT_EQ(labels.size(), 1u);
    EXPECT_EQ(labels[0]->text, "test");
    EXPECT_EQ(labels[0]->category(), TrackCategory::Text);
    EXPECT_EQ(labels[0]->position, (TrackPosition{0, 0x14, 0x0d}));
    EXPECT_EQ(tileAt(page, 0xb12).category(), TrackCategory::RouteButton);
    EXPECT_EQ(tileAt(page, 0x312).category(), TrackCategory::Turntable);
    EXPECT_EQ(tileAt(page, 0xc19).type, "hosentraeger");
    // Three TrainControl extension types and TrainControl's own `.prot` key, each reported once.
    const std::vector<std::string> texts = pageMessages(diagnostics);
    ASSERT_EQ(texts.size(), 4u) << diagnostics.formatAll();
    EXPECT_NE(texts[0].find("unknown element key .prot"), std::string::npos) << texts[0];
    EXPECT_NE(texts[1].find("unknown element type 'custom_perm_left'"), std::string::npos) << texts[1];
    EXPECT_NE(texts[2].find("'custom_perm_right'"), std::string::npos) << texts[2];
    EXPECT_NE(texts[3].find("'custom_perm_y'"), std::string::npos) << texts[3];
    EXPECT_FALSE(diagnostics.hasErrors());
}

TEST(TrackPage, UnchangedModelWritesTheOriginalBytes) {
    for (const std::string_view file :
         {corpus::karben, corpus::gbs0, corpus::testPage, corpus::cs3TrackPlan}) {
        const std::string bytes = readCorpus(file);
        const auto [diagnostics, page] = readPageText(bytes);
        EXPECT_EQ(page.write().serialize(), bytes) << file;
    }
}

TEST(TrackPage, ChangingOneFieldChangesOneLine) {
    const std::string bytes = readCorpus(corpus::karben);
    const auto change = [&bytes](auto edit) {
        TrackPage page = readPageText(bytes).page;
        edit(page);
        return changedPageLines(bytes, page.write().serialize());
    };
    using Lines = std::vector<std::string>;
    // elements[3] is the rechtsweiche at 0x105: .drehung=3, .artikel=2, .text=23, .zustand=1.
    EXPECT_EQ(change([](TrackPage& p) { p.elements[3].rotation = 0; }), Lines{" .drehung=0"});
    EXPECT_EQ(change([](TrackPage& p) { p.elements[3].article = 40; }), Lines{" .artikel=40"});
    EXPECT_EQ(change([](TrackPage& p) { p.elements[3].text = "W 23"; }), Lines{" .text=W 23"});
    EXPECT_EQ(change([](TrackPage& p) { p.elements[3].state = 0; }), Lines{" .zustand=0"});
    EXPECT_EQ(change([](TrackPage& p) { p.elements[3].type = "linksweiche"; }), Lines{" .typ=linksweiche"});
    // elements[5] is the s88kontakt at 0x107 with .deviceId=0x100.
    EXPECT_EQ(change([](TrackPage& p) { p.elements[5].deviceId = 0x200; }), Lines{" .deviceId=0x200"});
}

TEST(TrackPage, MovedElementGetsANewHexId) {
    const std::string bytes = readCorpus(corpus::karben);
    TrackPage page = readPageText(bytes).page;
    page.elements[0].position = {0, 14, 4};
    const std::string written = page.write().serialize();
    EXPECT_EQ(changedPageLines(bytes, written), std::vector<std::string>{" .id=0x40e"});
    EXPECT_EQ(readPageText(written).page.elements[0].position, (TrackPosition{0, 14, 4}));
}

TEST(TrackPage, MovedElementWithoutIdGetsOneAsItsFirstLine) {
    const std::string text = "[gleisbildseite]\nversion\n .major=1\nelement\n .typ=gerade\n .artikel=-1\n";
    TrackPage page = readPageText(text).page;
    EXPECT_EQ(page.write().serialize(), text);
    page.elements[0].position = {0, 3, 1};
    EXPECT_EQ(page.write().serialize(),
              "[gleisbildseite]\nversion\n .major=1\nelement\n .id=0x103\n .typ=gerade\n .artikel=-1\n");
}

TEST(TrackPage, IdStaysOmittedAtTheOrigin) {
    const std::string text = "[gleisbildseite]\nelement\n .typ=gerade\nelement\n .id=0x205\n .typ=bogen\n";
    TrackPage page = readPageText(text).page;
    page.elements[0].position = {};
    page.elements[1].position = {};
    EXPECT_EQ(page.write().serialize(),
              "[gleisbildseite]\nelement\n .typ=gerade\nelement\n .id=0x0\n .typ=bogen\n");
}

TEST(TrackPage, AddAndRemoveElements) {
    const std::string bytes = readCorpus(corpus::karben);
    TrackPage page = readPageText(bytes).page;
    page.elements.erase(page.elements.begin() + 5);
    TrackElement signal = element(0x20e, "signal", 30);
    signal.rotation = 1;
    signal.text = "N";
    page.elements.push_back(signal);
    const std::string written = page.write().serialize();
    EXPECT_NE(written.find("element\n .id=0x20e\n .typ=signal\n .drehung=1\n .artikel=30\n .text=N\n"),
              std::string::npos);
    const auto [diagnostics, reread] = readPageText(written);
    EXPECT_TRUE(diagnostics.empty()) << diagnostics.formatAll();
    expectSameElements(reread.elements, page.elements);
    EXPECT_EQ(reread.elements.size(), 37u);
}

TEST(TrackPage, AddToAFileWithoutFinalNewline) {
    const std::string bytes = readCorpus(corpus::testPage);
    ASSERT_NE(bytes.back(), '\n');
    TrackPage page = readPageText(bytes).page;
    page.elements.push_back(element(0x1001, "prellbock"));
    page.elements[100].text = "end";
    const auto [diagnostics, reread] = readPageText(page.write().serialize());
    expectSameElements(reread.elements, page.elements);
    EXPECT_EQ(reread.elements.size(), 102u);
}

TEST(TrackPage, NewPageWrittenTheWayACs2WritesOne) {
    TrackPage page;
    page.elements.push_back(element(0x0, "gerade"));
    TrackElement turnout = element(0x102, "linksweiche", 6);
    turnout.rotation = 2;
    page.elements.push_back(turnout);
    TrackElement label;
    label.position = {0, 4, 1};
    label.text = "Bf";
    page.elements.push_back(label);
    const std::string written = page.write().serialize();
    EXPECT_EQ(written, "[gleisbildseite]\nversion\n .major=1\n"
                       "element\n .typ=gerade\n .artikel=-1\n"
                       "element\n .id=0x102\n .typ=linksweiche\n .drehung=2\n .artikel=6\n"
                       "element\n .id=0x104\n .artikel=-1\n .text=Bf\n");
    const auto [diagnostics, reread] = readPageText(written);
    // The tile at the origin has no `.id`, as in real files; reading it back says so, once.
    ASSERT_EQ(diagnostics.items().size(), 1u) << diagnostics.formatAll();
    EXPECT_EQ(diagnostics.items()[0].message, "1 element(s) without .id, the first one here (reported once)");
    expectSameElements(reread.elements, page.elements);
}

TEST(TrackPage, ALabelStaysOnOneLine) {
    TrackPage page = readPageText("[gleisbildseite]\nelement\n .id=0x101\n .typ=text\n").page;
    page.elements[0].text = "Gleis 1\nelement";
    const auto [diagnostics, reread] = readPageText(page.write().serialize());
    ASSERT_EQ(reread.elements.size(), 1u);
    EXPECT_EQ(reread.elements[0].text, "Gleis 1 element");
}

TEST(TrackPage, CrLfFileGetsCrLfLines) {
    const std::string text = "[gleisbildseite]\r\nelement\r\n .id=0x101\r\n .typ=gerade\r\n";
    TrackPage page = readPageText(text).page;
    page.elements[0].text = "A";
    EXPECT_EQ(page.write().serialize(),
              "[gleisbildseite]\r\nelement\r\n .id=0x101\r\n .typ=gerade\r\n .text=A\r\n");
}

TEST(TrackPage, ElementsWithoutIdAreReportedOnce) {
    const auto [diagnostics, page] =
        readPageText("[gleisbildseite]\nelement\n .typ=text\n .text=A\nelement\n .id=0x101\n .typ=gerade\n"
                     "element\n .text=B\n");
    ASSERT_EQ(page.elements.size(), 3u);
    EXPECT_EQ(page.elements[0].position, TrackPosition{});
    EXPECT_EQ(page.elements[2].position, TrackPosition{});
    EXPECT_EQ(page.elements[2].category(), TrackCategory::Text);
    const std::vector<std::string> texts = pageMessages(diagnostics);
    ASSERT_EQ(texts.size(), 1u) << diagnostics.formatAll();
    EXPECT_EQ(texts[0], "page.cs2:2: warning: 2 element(s) without .id, the first one here (reported once); "
                        "placed at page 0, column 0, row 0 as a CS2 does");
}

TEST(TrackPage, TwoElementsOnOneTileAreKeptAndReported) {
    const auto [diagnostics, page] = readPageText(
        "[gleisbildseite]\nelement\n .id=0x102\n .typ=gerade\nelement\n .id=0x102\n .typ=signal\n");
    EXPECT_EQ(page.elements.size(), 2u);
    const std::vector<std::string> texts = pageMessages(diagnostics);
    ASSERT_EQ(texts.size(), 1u) << diagnostics.formatAll();
    EXPECT_EQ(texts[0], "page.cs2:5: warning: two elements at page 0, column 2, row 1 (also line 2); "
                        "both are kept; the later one is drawn on top");
}

TEST(TrackPage, UnreadableValuesAreReportedAndKept) {
    const std::string text = "[gleisbildseite]\nelement\n .id=zz\n .typ=signal\n .drehung=7\n .artikel=abc\n"
                             " .zustand=-2\n";
    auto [diagnostics, page] = readPageText(text);
    const TrackElement& read = page.elements.at(0);
    EXPECT_EQ(read.position, TrackPosition{});
    EXPECT_EQ(read.rotation, 0);
    EXPECT_EQ(read.article, -1);
    EXPECT_EQ(read.state, 0);
    const std::vector<std::string> texts = pageMessages(diagnostics);
    ASSERT_EQ(texts.size(), 4u) << diagnostics.formatAll();
    EXPECT_EQ(texts[0], "page.cs2:3: warning: element .id 'zz' is not a number; placed at column 0, row 0; "
                        "the line is kept as it is");
    EXPECT_EQ(texts[1],
              "page.cs2:5: warning: element .drehung 7 is outside 0..3; 0 used; the line is kept as it is");
    EXPECT_EQ(texts[2],
              "page.cs2:6: warning: element .artikel 'abc' is not a number; -1 used; the line is kept "
              "as it is");
    EXPECT_EQ(texts[3],
              "page.cs2:7: warning: element .zustand -2 is outside 0..2147483647; 0 used; the line is "
              "kept as it is");
    EXPECT_EQ(page.write().serialize(), text);
    page.elements[0].rotation = 2;
    EXPECT_EQ(changedPageLines(text, page.write().serialize()), std::vector<std::string>{" .drehung=2"});
}

TEST(TrackPage, IdOutsideTheGridIsReported) {
    const auto [diagnostics, page] =
        readPageText("[gleisbildseite]\nelement\n .id=0x1000000\n .typ=gerade\n");
    EXPECT_EQ(page.elements.at(0).position, TrackPosition{});
    ASSERT_EQ(diagnostics.items().size(), 1u);
    EXPECT_EQ(diagnostics.items()[0].message,
              "element .id 0x1000000 is outside 0x0..0xffffff (page, row, column)");
}

TEST(TrackPage, UnknownTypesAndKeysAreReportedOnceEach) {
    const auto [diagnostics, page] =
        readPageText("[gleisbildseite]\nelement\n .id=0x101\n .typ=magic\n .farbe=rot\nelement\n .id=0x102\n"
                     " .typ=magic\n .farbe=gruen\nelement\n .id=0x103\n .typ=gerade\n");
    ASSERT_EQ(page.elements.size(), 3u);
    EXPECT_EQ(page.elements[0].category(), TrackCategory::Unknown);
    EXPECT_EQ(page.elements[0].elementType(), nullptr);
    EXPECT_FALSE(page.elements[0].switchable());
    const std::vector<std::string> texts = pageMessages(diagnostics);
    ASSERT_EQ(texts.size(), 2u) << diagnostics.formatAll();
    EXPECT_EQ(texts[0], "page.cs2:5: warning: unknown element key .farbe (reported once); kept unchanged");
    EXPECT_EQ(texts[1],
              "page.cs2:2: warning: unknown element type 'magic' (not a CS2/CS3 type we know; reported "
              "once); kept unchanged; shown as an unknown tile");
}

TEST(TrackPage, KeyGivenTwiceUsesTheFirst) {
    const auto [diagnostics, page] =
        readPageText("[gleisbildseite]\nelement\n .id=0x101\n .typ=gerade\n .typ=bogen\n");
    EXPECT_EQ(page.elements.at(0).type, "gerade");
    ASSERT_EQ(diagnostics.items().size(), 1u);
    EXPECT_EQ(
        diagnostics.format(diagnostics.items()[0]),
        "page.cs2:5: warning: element has .typ twice (also line 4); the first one is used; both are kept");
}

TEST(TrackPage, ElementWithoutTypeOrText) {
    const auto [diagnostics, page] = readPageText("[gleisbildseite]\nelement\n .id=0x101\n");
    EXPECT_EQ(page.elements.at(0).category(), TrackCategory::Text);
    ASSERT_EQ(diagnostics.items().size(), 1u);
    EXPECT_EQ(diagnostics.items()[0].message, "element without .typ and without .text");
}

TEST(TrackPage, UnknownRecordsAreKeptAndReportedOnce) {
    const std::string text = "[gleisbildseite]\nversion\n .major=1\nhintergrund\n .bild=a.png\nhintergrund\n"
                             "element\n .id=0x101\n .typ=gerade\n";
    auto [diagnostics, page] = readPageText(text);
    ASSERT_EQ(diagnostics.items().size(), 1u) << diagnostics.formatAll();
    EXPECT_EQ(diagnostics.format(diagnostics.items()[0]),
              "page.cs2:4: warning: unknown record 'hintergrund' (reported once); kept unchanged");
    page.elements[0].rotation = 1;
    EXPECT_EQ(page.write().serialize(), text + " .drehung=1\n");
}

TEST(TrackPage, Cs3TrackPlanIsRefusedClearly) {
    const std::string bytes = readCorpus(corpus::cs3TrackPlan);
    const auto [diagnostics, page] = readPageText(bytes);
    EXPECT_EQ(page.format, TrackPlanFormat::Cs3Pixels);
    EXPECT_TRUE(page.elements.empty());
    ASSERT_EQ(diagnostics.items().size(), 1u) << diagnostics.formatAll();
    const Diagnostic& only = diagnostics.items()[0];
    EXPECT_EQ(only.severity, Diagnostic::Severity::Error);
    EXPECT_EQ(only.message.rfind("CS3 track plan format (pixel coordinates) is not supported; ", 0), 0u)
        << only.message;
    EXPECT_EQ(page.write().serialize(), bytes);
}

TEST(TrackPage, OtherSectionIsReadWithAWarning) {
    const auto [diagnostics, page] = readPageText("[gleisbild]\nelement\n .id=0x101\n .typ=gerade\n");
    EXPECT_EQ(page.elements.size(), 1u);
    ASSERT_EQ(diagnostics.items().size(), 1u);
    EXPECT_EQ(diagnostics.format(diagnostics.items()[0]),
              "page.cs2:1: warning: section [gleisbild] where [gleisbildseite] was expected; read as a track "
              "plan page anyway");
}

TEST(TrackPage, Json) {
    const std::string karben = toJson(readCorpusPage(corpus::karben).page);
    EXPECT_NE(karben.find("\"columns\": 14"), std::string::npos);
    EXPECT_NE(karben.find("\"rows\": 4"), std::string::npos);
    EXPECT_NE(karben.find("\"id\": \"0x105\",\n      \"type\": \"rechtsweiche\",\n      \"category\": "
                          "\"turnout\",\n      \"switchable\": true,\n      \"rotation\": 3"),
              std::string::npos)
        << karben.substr(0, 1200);
    const std::string test = toJson(readCorpusPage(corpus::testPage).page);
    EXPECT_NE(test.find("\"type\": null,\n      \"category\": \"text\""), std::string::npos);
    EXPECT_NE(test.find("\"category\": \"unknown\""), std::string::npos);
}
