#include "cs2config/TrackStatus.h"

#include "ConfigTestSupport.h"

#include <gtest/gtest.h>

using namespace stellwerk::cs2config;
using namespace stellwerk::cs2config::test;

namespace {

struct ReadStatus {
    Diagnostics diagnostics;
    TrackStatusFile status;
};

ReadStatus readStatusText(std::string_view text) {
    Parsed parsed = parseText(text, "gleisbild.sr2");
    TrackStatusFile status = TrackStatusFile::read(parsed.document, parsed.diagnostics);
    return {std::move(parsed.diagnostics), std::move(status)};
}

TrackElementStatus entry(std::int64_t id, std::int64_t state) {
    TrackElementStatus made;
    made.id = id;
    made.state = state;
    return made;
}

// The form mrsystem's gbsstat.c writes: decimal numbers, `.zustand` left out when 0.
constexpr std::string_view writtenByMrsystem = "[gleisbild]\n"
                                               "version\n"
                                               " .major=0\n"
                                               " .minor=1\n"
                                               "element\n"
                                               " .id=258\n"
                                               " .zustand=1\n"
                                               "element\n"
                                               " .id=263\n";

} // namespace

TEST(TrackStatus, MrsystemStatusFile) {
    auto [diagnostics, status] = readStatusText(writtenByMrsystem);
    EXPECT_TRUE(diagnostics.empty()) << diagnostics.formatAll();
    EXPECT_EQ(status.version, (TrackFileVersion{0, 1}));
    ASSERT_EQ(status.elements.size(), 2u);
    EXPECT_EQ(status.elements[0].id, 258);
    EXPECT_EQ(status.elements[0].state, 1);
    EXPECT_EQ(status.elements[1].id, 263);
    EXPECT_EQ(status.elements[1].state, 0);
    EXPECT_EQ(status.find(263), &status.elements[1]);
    EXPECT_EQ(status.find(1), nullptr);
    EXPECT_EQ(status.write().serialize(), writtenByMrsystem);
}

// The CS2 web server emulations serve an empty status file: header and version only.
TEST(TrackStatus, EmptyStatusFile) {
    const auto [diagnostics, status] = readStatusText("[gleisbild]\nversion\n .minor=1\n");
    EXPECT_TRUE(diagnostics.empty()) << diagnostics.formatAll();
    EXPECT_EQ(status.version, (TrackFileVersion{0, 1}));
    EXPECT_TRUE(status.elements.empty());
}

TEST(TrackStatus, NewFileIsWrittenAsMrsystemWritesIt) {
    TrackStatusFile status;
    status.elements.push_back(entry(258, 1));
    status.elements.push_back(entry(263, 0));
    EXPECT_EQ(status.write().serialize(), writtenByMrsystem);
}

TEST(TrackStatus, ChangingAStateChangesOneLine) {
    TrackStatusFile status = readStatusText(writtenByMrsystem).status;
    status.elements[0].state = 2;
    std::string expected(writtenByMrsystem);
    expected.replace(expected.find(" .zustand=1"), 11, " .zustand=2");
    EXPECT_EQ(status.write().serialize(), expected);
    status.elements[1].state = 3;
    expected += " .zustand=3\n";
    EXPECT_EQ(status.write().serialize(), expected);
}

TEST(TrackStatus, AddAndRemoveEntries) {
    TrackStatusFile status = readStatusText(writtenByMrsystem).status;
    status.elements.erase(status.elements.begin());
    status.elements.push_back(entry(0x30f, 2));
    const auto [diagnostics, reread] = readStatusText(status.write().serialize());
    EXPECT_TRUE(diagnostics.empty()) << diagnostics.formatAll();
    ASSERT_EQ(reread.elements.size(), 2u);
    EXPECT_EQ(reread.elements[0].id, 263);
    EXPECT_EQ(reread.elements[1].id, 0x30f);
    EXPECT_EQ(reread.elements[1].state, 2);
}

TEST(TrackStatus, HexIdsAndProblems) {
    const std::string text = "[gleisbild]\nelement\n .id=0x102\n .zustand=1\nelement\n .id=258\n .farbe=3\n"
                             "element\n .zustand=x\n";
    const auto [diagnostics, status] = readStatusText(text);
    ASSERT_EQ(status.elements.size(), 3u);
    EXPECT_EQ(status.elements[0].id, 0x102);
    std::vector<std::string> texts;
    for (const Diagnostic& diagnostic : diagnostics.items())
        texts.push_back(diagnostics.format(diagnostic));
    ASSERT_EQ(texts.size(), 4u) << diagnostics.formatAll();
    EXPECT_EQ(texts[0],
              "gleisbild.sr2:7: warning: unknown status element key .farbe (reported once); kept unchanged");
    EXPECT_EQ(texts[1],
              "gleisbild.sr2:5: warning: second status for element 258 (also line 2); both are kept; "
              "find() gives the first one");
    EXPECT_EQ(texts[2], "gleisbild.sr2:8: warning: status element without .id; kept; read as id 0");
    EXPECT_EQ(texts[3],
              "gleisbild.sr2:9: warning: status element .zustand 'x' is not a number; 0 used; the line "
              "is kept as it is");
    EXPECT_EQ(status.write().serialize(), text);
}

TEST(TrackStatus, Json) {
    const std::string json = toJson(readStatusText(writtenByMrsystem).status);
    EXPECT_NE(json.find("\"id\": 258,\n      \"state\": 1"), std::string::npos) << json;
}
