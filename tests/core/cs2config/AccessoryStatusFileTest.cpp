// magnetartikel.sr2 (config-data key "magstat"), the accessory status file. No corpus file holds one;
// the fixtures follow the format public programs read and serve (see AccessoryStatusFile.h).

#include "cs2config/AccessoryStatusFile.h"

#include "ConfigTestSupport.h"

#include <random>

namespace stellwerk::cs2config::test {
namespace {

// What RailControl's CS2 HTTP server answers for /config/magnetartikel.sr2: no accessory has a state.
constexpr std::string_view emptyStatus = "[magnetartikel]\nversion\n .minor=1\n";

// The records JCS reads: `.id` and `.stellung`, a missing `.stellung` meaning 0.
constexpr std::string_view threeStates = "[magnetartikel]\n"
                                         "version\n"
                                         " .minor=1\n"
                                         "artikel\n"
                                         " .id=1\n"
                                         " .stellung=1\n"
                                         "artikel\n"
                                         " .id=2\n"
                                         "artikel\n"
                                         " .id=5\n"
                                         " .stellung=2\n";

using ReadStatusFile = ReadModel<AccessoryStatusFile>;

ReadStatusFile readStatusFile(std::string_view text) {
    return readAs<AccessoryStatusFile>(text, "magnetartikel.sr2");
}

TEST(AccessoryStatusFile, EmptyStatusFileAsServedByRailControl) {
    ReadStatusFile read = readStatusFile(emptyStatus);
    EXPECT_TRUE(read.diagnostics.empty()) << read.diagnostics.formatAll();
    EXPECT_TRUE(read.file.states.empty());
    EXPECT_EQ(read.file.versionMinor, 1);
    EXPECT_EQ(read.file.write().serialize(), emptyStatus);
}

TEST(AccessoryStatusFile, StatesAreRead) {
    ReadStatusFile read = readStatusFile(threeStates);
    EXPECT_TRUE(read.diagnostics.empty()) << read.diagnostics.formatAll();
    ASSERT_EQ(read.file.states.size(), 3u);
    EXPECT_EQ(read.file.states[0].id, 1);
    EXPECT_EQ(read.file.states[0].position, 1);
    EXPECT_EQ(read.file.states[1].id, 2);
    EXPECT_EQ(read.file.states[1].position, 0);
    EXPECT_EQ(read.file.states[2].position, 2);
    EXPECT_EQ(read.file.states[2].lineNumber(), 9);
    ASSERT_NE(read.file.find(5), nullptr);
    EXPECT_EQ(read.file.find(5)->position, 2);
    EXPECT_EQ(read.file.find(3), nullptr);
    EXPECT_EQ(read.file.write().serialize(), threeStates);
}

TEST(AccessoryStatusFile, ChangingOneStateChangesOnlyItsLine) {
    ReadStatusFile read = readStatusFile(threeStates);
    read.file.states[0].position = 0;
    read.file.states[1].position = 1;
    EXPECT_EQ(read.file.write().serialize(),
              "[magnetartikel]\nversion\n .minor=1\nartikel\n .id=1\n .stellung=0\n"
              "artikel\n .id=2\n .stellung=1\nartikel\n .id=5\n .stellung=2\n");
}

TEST(AccessoryStatusFile, AddedAndRemovedStatesReadBackTheSame) {
    ReadStatusFile read = readStatusFile(threeStates);
    read.file.states.erase(read.file.states.begin());
    AccessoryState added;
    added.id = 9;
    added.position = 3;
    read.file.states.push_back(added);
    const std::string written = read.file.write().serialize();
    EXPECT_EQ(written, "[magnetartikel]\nversion\n .minor=1\nartikel\n .id=2\nartikel\n .id=5\n .stellung=2\n"
                       "artikel\n .id=9\n .stellung=3\n");
    ReadStatusFile again = readStatusFile(written);
    EXPECT_TRUE(again.diagnostics.empty()) << again.diagnostics.formatAll();
    ASSERT_EQ(again.file.states.size(), 3u);
    EXPECT_EQ(again.file.states[2].id, 9);
    EXPECT_EQ(again.file.states[2].position, 3);
}

TEST(AccessoryStatusFile, NewStatusFileLooksLikeTheStations) {
    AccessoryStatusFile file;
    file.versionMinor = 1;
    EXPECT_EQ(file.write().serialize(), emptyStatus);
    file.states.push_back({7, 1, {}});
    EXPECT_EQ(file.write().serialize(),
              "[magnetartikel]\nversion\n .minor=1\nartikel\n .id=7\n .stellung=1\n");
}

TEST(AccessoryStatusFile, ProblemsAreReported) {
    ReadStatusFile read =
        readStatusFile("[magnetartikel]\nartikel\n .id=1\n .stellung=rot\n .zeit=5\n"
                       "artikel\n .id=1\n .zeit=6\nartikel\n .stellung=1\nfahrstrasse\n .id=1\n");
    ASSERT_EQ(read.diagnostics.count(), 5u) << read.diagnostics.formatAll();
    EXPECT_EQ(read.diagnostics.items()[0].line, 5);
    EXPECT_EQ(read.diagnostics.items()[0].message, "unknown key '.zeit' in artikel records");
    EXPECT_EQ(read.diagnostics.items()[1].line, 4);
    EXPECT_EQ(read.diagnostics.items()[1].message,
              "value 'rot' of .stellung in artikel record is not a number");
    EXPECT_EQ(read.diagnostics.items()[2].line, 9);
    EXPECT_EQ(read.diagnostics.items()[2].message, "artikel record without .id");
    EXPECT_EQ(read.diagnostics.items()[3].line, 11);
    EXPECT_EQ(read.diagnostics.items()[3].message, "unknown record 'fahrstrasse'");
    EXPECT_EQ(read.diagnostics.items()[4].line, 6);
    EXPECT_EQ(read.diagnostics.items()[4].message, "state of accessory 1 given again (first at line 2)");
    EXPECT_EQ(read.file.states.size(), 3u);
}

TEST(AccessoryStatusFile, OtherSectionIsReported) {
    ReadStatusFile read = readStatusFile("[gleisbild]\nversion\n .minor=1\n");
    ASSERT_EQ(read.diagnostics.count(), 1u);
    EXPECT_EQ(read.diagnostics.items()[0].message, "section [gleisbild] instead of [magnetartikel]");
}

TEST(AccessoryStatusFile, JsonListsTheStates) {
    EXPECT_EQ(toJson(readStatusFile(threeStates).file), R"({
  "file": "magnetartikel.sr2",
  "version": {
    "major": null,
    "minor": 1
  },
  "states": [
    {
      "line": 4,
      "id": 1,
      "position": 1
    },
    {
      "line": 7,
      "id": 2,
      "position": 0
    },
    {
      "line": 9,
      "id": 5,
      "position": 2
    }
  ]
}
)");
}

TEST(AccessoryStatusFile, DamagedFilesAreReadAndWrittenBack) {
    std::string original(threeStates);
    for (int id = 10; id < 60; ++id)
        original += "artikel\n .id=" + std::to_string(id) + "\n .stellung=" + std::to_string(id % 4) + "\n";
    std::mt19937 random(7);
    for (int round = 0; round < 2000; ++round) {
        const std::string bytes = damaged(original, random);
        Parsed parsed = parseText(bytes);
        ASSERT_EQ(parsed.document.serialize(), bytes) << "round " << round;
        const AccessoryStatusFile file = AccessoryStatusFile::read(parsed.document, parsed.diagnostics);
        const std::string written = file.write().serialize();
        Diagnostics again;
        EXPECT_EQ(AccessoryStatusFile::read(Document::parse(written, again), again).states.size(),
                  file.states.size())
            << "round " << round;
    }
}

} // namespace
} // namespace stellwerk::cs2config::test
