// `stellwerk-cli cs2 check|json|format`: .cs2 files checked, shown as JSON and written back.

#include "Cs2Command.h"

#include "CliTestSupport.h"
#include "CommandRuns.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <unistd.h>

using stellwerk::cli::test::corpus;
using stellwerk::cli::test::Outcome;
using stellwerk::cli::test::readFile;
namespace fs = std::filesystem;

using stellwerk::cli::test::cs2Command;

namespace {

// A scratch file that is removed again.
class ScratchFile {
public:
    ScratchFile(const std::string& name, const std::string& bytes)
        : path_(fs::temp_directory_path() /
                ("stellwerk-cs2-test-" + std::to_string(::getpid()) + "-" + name)) {
        std::ofstream(path_, std::ios::binary) << bytes;
    }
    ~ScratchFile() { fs::remove(path_); }
    std::string path() const { return path_.string(); }

private:
    fs::path path_;
};

const std::string karben = "GBert__railroad/can2udp/files/maerklin/config/gleisbilder/karben.cs2";
const std::string routes = "bob123456678__TrainControl/test/fahrstrassen.cs2";
const std::string articles = "GBert__railroad/can2udp/files/maerklin/config/magnetartikel.cs2";
const std::string cs3Plan = "RalfMende__LocDbConverterConsole/ExampleFiles/cs3/work/config/gbs/plneu/2.cs2";

TEST(Cs2Command, CheckSummarisesCleanFiles) {
    const Outcome outcome = cs2Command({"check", corpus(routes), corpus(articles), corpus(karben)});
    EXPECT_EQ(outcome.status, 0) << outcome.out;
    EXPECT_NE(outcome.out.find("fahrstrassen.cs2: ok - routes (fahrstrassen.cs2): 81 routes, 689 items\n"),
              std::string::npos)
        << outcome.out;
    EXPECT_NE(outcome.out.find("magnetartikel.cs2: ok - accessories (magnetartikel.cs2): 13 accessories\n"),
              std::string::npos);
    EXPECT_NE(outcome.out.find("karben.cs2: ok - track plan page: 37 elements\n"), std::string::npos);
}

TEST(Cs2Command, CheckListsProblemsWithLineNumbersAndStillAcceptsTheFile) {
    ScratchFile file("broken.cs2",
                     "[magnetartikel]\nartikel\n .id=1\n .typ=rechtsweiche\n?!\nartikel\n .id=2\n");
    const Outcome outcome = cs2Command({"check", file.path()});
    EXPECT_EQ(outcome.status, 0);
    EXPECT_NE(outcome.out.find(file.path() + ":5: warning: unreadable line '?!'"), std::string::npos)
        << outcome.out;
    EXPECT_NE(outcome.out.find(file.path() + ": usable, "), std::string::npos) << outcome.out;
}

TEST(Cs2Command, CheckFailsForFilesThatAreNotCs2) {
    ScratchFile text("notes.txt", "buy milk\nfix the turntable\n");
    ScratchFile binary("icon.png", std::string("\x89PNG\r\n\x1A\n\0\0\0\rIHDR", 16));
    for (const std::string& path : {text.path(), binary.path(), std::string("/nonexistent/lokomotive.cs2")}) {
        const Outcome outcome = cs2Command({"check", corpus(karben), path});
        EXPECT_EQ(outcome.status, 1) << path;
        EXPECT_NE(outcome.out.find(path + ": not a .cs2 file"), std::string::npos) << outcome.out;
    }
}

TEST(Cs2Command, Cs3TrackPlanIsNotUsable) {
    const Outcome outcome = cs2Command({"check", corpus(cs3Plan)});
    EXPECT_EQ(outcome.status, 1);
    EXPECT_NE(outcome.out.find("CS3 track plan format"), std::string::npos) << outcome.out;
    EXPECT_NE(outcome.out.find("not usable, 1 error"), std::string::npos) << outcome.out;
}

TEST(Cs2Command, JsonOfAPageListsEveryElementWithPosition) {
    const Outcome outcome = cs2Command({"json", corpus(karben)});
    ASSERT_EQ(outcome.status, 0) << outcome.err;
    EXPECT_EQ(outcome.err, "");
    std::size_t elements = 0;
    for (std::size_t at = outcome.out.find("\"type\""); at != std::string::npos;
         at = outcome.out.find("\"type\"", at + 1))
        ++elements;
    EXPECT_EQ(elements, 37u);
    for (const char* key : {"\"page\"", "\"x\"", "\"y\"", "\"rotation\"", "\"article\"", "\"text\""})
        EXPECT_NE(outcome.out.find(key), std::string::npos) << key;
    // karben's first element, 0x102: page 0, x 2, y 1 (field notes: y in bits 8-15, x in bits 0-7).
    EXPECT_NE(outcome.out.find("\"page\": 0,\n      \"x\": 2,\n      \"y\": 1,\n      \"id\": \"0x102\""),
              std::string::npos)
        << outcome.out.substr(0, 600);
}

TEST(Cs2Command, CheckOfTheCorruptedLocoListNamesTheBrokenLine) {
    const Outcome outcome =
        cs2Command({"check", corpus("joao404__z21MaerklinCan/data/config/lokomotive.cs2")});
    EXPECT_EQ(outcome.status, 0) << "usable with warnings";
    EXPECT_NE(outcome.out.find("lokomotive.cs2:7: warning: unreadable line ' komotive]'"), std::string::npos)
        << outcome.out;
    EXPECT_NE(outcome.out.find("locomotives (lokomotive.cs2): 5 locomotives, 64 functions"),
              std::string::npos);
}

TEST(Cs2Command, JsonOfLocomotivesListsTheirFunctions) {
    const Outcome outcome =
        cs2Command({"json", corpus("RalfMende__srseii-portal/package/var/lokomotive.cs2")});
    ASSERT_EQ(outcome.status, 0);
    EXPECT_NE(outcome.out.find("\"locomotiveCount\": 9"), std::string::npos) << outcome.out.substr(0, 300);
    EXPECT_NE(outcome.out.find("\"functions\": ["), std::string::npos);
    EXPECT_NE(outcome.err.find("duplicate uid 0x4005"), std::string::npos) << outcome.err;
}

TEST(Cs2Command, JsonOfRoutes) {
    const Outcome outcome = cs2Command({"json", corpus(routes)});
    ASSERT_EQ(outcome.status, 0);
    EXPECT_NE(outcome.out.find("\"name\": \"sk reset\""), std::string::npos) << outcome.out.substr(0, 400);
}

TEST(Cs2Command, JsonOfAnIndexWithItsPageFolderShowsTheLayout) {
    const Outcome outcome =
        cs2Command({"json", corpus("bob123456678__TrainControl/cs2_sample_layout/config/gleisbild.cs2")});
    ASSERT_EQ(outcome.status, 0);
    EXPECT_NE(outcome.out.find("\"5 - Test\""), std::string::npos);
    EXPECT_NE(outcome.out.find("custom_perm_left"), std::string::npos) << "elements of page 5 are included";
    EXPECT_NE(outcome.err.find("gleisbilder/1 - Main.cs2"), std::string::npos) << outcome.err;
}

TEST(Cs2Command, FormatReproducesEveryCorpusFile) {
    for (const std::string& file : {karben, routes, articles,
                                    std::string("bob123456678__TrainControl/cs2_sample_layout/"
                                                "config/gleisbilder/5 - Test.cs2")}) {
        const Outcome outcome = cs2Command({"format", corpus(file)});
        EXPECT_EQ(outcome.status, 0) << file;
        EXPECT_EQ(outcome.out, readFile(corpus(file))) << file;
    }
}

TEST(Cs2Command, FormatWritesToAFile) {
    ScratchFile target("out.cs2", "");
    const Outcome outcome = cs2Command({"format", corpus(articles), "-o", target.path()});
    EXPECT_EQ(outcome.status, 0);
    EXPECT_EQ(outcome.out, "");
    EXPECT_EQ(readFile(target.path()), readFile(corpus(articles)));
}

TEST(Cs2Command, FormatRefusesAFileThatIsNotCs2AndWritesNothing) {
    ScratchFile text("notes.txt", "buy milk\n");
    ScratchFile target("untouched.cs2", "keep me");
    const Outcome outcome = cs2Command({"format", text.path(), "-o", target.path()});
    EXPECT_EQ(outcome.status, 1);
    EXPECT_EQ(readFile(target.path()), "keep me");
}

// Issue 11 (found by fuzzing): a stray ".artikel" or ".fahrstrasse" line outside any record was
// dropped by `cs2 format` although the warning said it was kept.
TEST(Cs2Command, FormatKeepsStrayRecordLinesAsTheWarningSays) {
    for (const std::string bytes : {"[magnetartikel]\n.artikel\nartikel\n .id=1\n .typ=standardweiche\n",
                                    "[fahrstrassen]\n.fahrstrasse\nfahrstrasse\n .id=2\n .name=FS 2\n"}) {
        const ScratchFile file("stray.cs2", bytes);
        const Outcome outcome = cs2Command({"format", file.path()});
        EXPECT_EQ(outcome.status, 0) << outcome.err;
        EXPECT_NE(outcome.err.find(":2: warning: "), std::string::npos) << outcome.err;
        EXPECT_NE(outcome.err.find("kept"), std::string::npos) << outcome.err;
        EXPECT_EQ(outcome.out, bytes);
    }
}

// Issue 11 (found by the long cs2_document run): a stray ".lokomotive" line outside any record was
// read as a locomotive, and `cs2 format` then wrote it twice.
TEST(Cs2Command, StrayLocomotiveLineIsNotALocomotive) {
    const std::string bytes = "[lokomotive]\n.lokomotive\nlokomotive\n .name=BR 01\n .uid=0x4001\n";
    const ScratchFile file("lokomotive.cs2", bytes);
    const Outcome format = cs2Command({"format", file.path()});
    EXPECT_EQ(format.status, 0) << format.err;
    EXPECT_EQ(format.out, bytes);
    const Outcome json = cs2Command({"json", file.path()});
    EXPECT_EQ(json.status, 0) << json.err;
    EXPECT_NE(json.out.find("\"BR 01\""), std::string::npos) << json.out;
    EXPECT_EQ(json.out.find("\"name\":\"\""), std::string::npos) << json.out;
}

// Issue 11 (found by fuzzing): "#cc" in a CS3 loco file became the byte 0xCC, and `cs2 json` wrote
// invalid UTF-8. Escaped bytes above 0x7F are Latin-1 characters unless they form UTF-8.
TEST(Cs2Command, JsonOfCs3EscapesIsUtf8) {
    const ScratchFile file("cs3.cs2", "[lokomotive]\nlokomotive\n .name=Gro#DFe#20Lok\n .dectyp=#cc\n");
    const Outcome outcome = cs2Command({"json", file.path()});
    EXPECT_EQ(outcome.status, 0) << outcome.err;
    EXPECT_NE(outcome.out.find("\"Gro\u00dfe Lok\""), std::string::npos) << outcome.out;
    EXPECT_EQ(outcome.out.find('\xcc'), std::string::npos) << outcome.out;
    EXPECT_NE(outcome.out.find("\u00cc"), std::string::npos) << outcome.out;
}

TEST(Cs2Command, UsageErrors) {
    EXPECT_EQ(cs2Command({}).status, 2);
    EXPECT_EQ(cs2Command({"check"}).status, 2);
    EXPECT_EQ(cs2Command({"json"}).status, 2);
    EXPECT_EQ(cs2Command({"json", "a", "b"}).status, 2);
    EXPECT_EQ(cs2Command({"format"}).status, 2);
    EXPECT_EQ(cs2Command({"frobnicate"}).status, 2);
    EXPECT_NE(cs2Command({"frobnicate"}).err.find("usage: stellwerk-cli cs2 check"), std::string::npos);
}

} // namespace
