// `stellwerk-cli cs2 check DIR`: a layout folder checked file by file and then as a whole, and damaged
// headers read as what the file's name says.

#include "CliTestSupport.h"
#include "CommandRuns.h"
#include "Cs2Command.h"

#include <QTemporaryDir>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

using stellwerk::cli::test::corpus;
using stellwerk::cli::test::Outcome;
namespace fs = std::filesystem;

using stellwerk::cli::test::cs2Command;

namespace {

// A scratch layout folder: config/<path> for each file.
class ScratchFolder {
public:
    void add(const std::string& path, const std::string& bytes) {
        const fs::path file = config() / path;
        fs::create_directories(file.parent_path());
        std::ofstream(file, std::ios::binary) << bytes;
    }
    std::string path() const { return dir_.path().toStdString(); }
    fs::path config() const { return fs::path(path()) / "config"; }

private:
    QTemporaryDir dir_;
};

const std::string gbertFolder = "GBert__railroad/can2udp/files/maerklin";

TEST(Cs2CheckFolder, ACorpusFolderIsCheckedFileByFileAndAsAWhole) {
    const std::string folder = corpus(gbertFolder);
    const Outcome outcome = cs2Command({"check", folder});
    EXPECT_EQ(outcome.status, 0) << outcome.out;
    const std::string config = folder + "/config/";
    for (const std::string& line : {config + "gleisbild.cs2: ok - track plan index (gleisbild.cs2): 1 page\n",
                                    config + "gleisbilder/karben.cs2: ok - track plan page: 37 elements\n",
                                    config + "magnetartikel.cs2: ok - accessories (magnetartikel.cs2): 13 "
                                             "accessories\n"})
        EXPECT_NE(outcome.out.find(line), std::string::npos) << line << "\n" << outcome.out;
    EXPECT_NE(outcome.out.find(config +
                               "gleisbilder/karben.cs2:16: warning: tile '23' (rechtsweiche at column 5, "
                               "row 1) and 2 other tiles switch the same article 1 '23' (.artikel=2)"),
              std::string::npos)
        << outcome.out;
    EXPECT_NE(outcome.out.find(folder + ": usable as a layout, 13 layout warnings - 1 page\n"),
              std::string::npos)
        << outcome.out;
}

TEST(Cs2CheckFolder, MissingPagesAndADamagedHeaderAreWarningsOfAUsableFolder) {
    ScratchFolder folder;
    folder.add("gleisbild.cs2", "[gleisbild]\nseite\n .id=1\n .name=Bahnhof\nseite\n .id=2\n .name=Bw\n");
    folder.add("gleisbilder/Bahnhof.cs2", "Bau [gleisbildseite]\nelement\n .id=0x102\n .typ=gerade\n");
    folder.add("magnetartikel.cs2", "[magnetart\nartikel\n .id=1\n .typ=rechtsweiche\n");
    const Outcome outcome = cs2Command({"check", folder.path()});
    EXPECT_EQ(outcome.status, 0) << outcome.out;
    const std::string config = folder.config().string() + "/";
    for (const std::string& line :
         {config +
              "gleisbilder/Bahnhof.cs2:1: warning: 'Bau ' in front of the section header [gleisbildseite]; "
              "read as the header; the text in front of it is kept unchanged\n",
          config + "gleisbilder/Bahnhof.cs2: usable, 1 warning - track plan page: 1 element\n",
          config + "magnetartikel.cs2: warning: no readable section header; read as accessories "
                   "(magnetartikel.cs2) because of the file name\n",
          config + "gleisbild.cs2:5: warning: page 2 'Bw' is listed, but its file 'gleisbilder/Bw.cs2' is "
                   "missing; "
                   "the page stays empty\n",
          folder.path() + ": usable as a layout, 1 layout warning - 2 pages\n"})
        EXPECT_NE(outcome.out.find(line), std::string::npos) << line << "\n" << outcome.out;
}

TEST(Cs2CheckFolder, AFolderWithoutTrackPlanIsNotUsable) {
    ScratchFolder folder;
    folder.add("lokomotive.cs2", "[lokomotive]\nlokomotive\n .name=V 100\n");
    const Outcome outcome = cs2Command({"check", folder.path()});
    EXPECT_EQ(outcome.status, 1);
    EXPECT_NE(outcome.out.find(folder.path() +
                               ": not usable - there is no track plan (config/gleisbild.cs2, or pages in "
                               "config/gleisbilder/)"),
              std::string::npos)
        << outcome.out;
}

// Issue 32: the pages of a folder whose gleisbild.cs2 is missing are checked, and the missing index said.
TEST(Cs2CheckFolder, PagesWithoutTheirIndexAreCheckedAndTheIndexReportedMissing) {
    ScratchFolder folder;
    folder.add("gleisbilder/Bahnhof.cs2", "[gleisbildseite]\nelement\n .id=0x101\n .typ=gerade\n");
    const Outcome outcome = cs2Command({"check", folder.path()});
    EXPECT_EQ(outcome.status, 0) << outcome.out;
    for (const std::string& line :
         {std::string("gleisbild.cs2: warning: the track plan index is missing; the 1 page file(s) in "
                      "gleisbilder/ are shown in the order of their names, numbered from 0\n"),
          folder.config().string() + "/gleisbilder/Bahnhof.cs2: ok - track plan page: 1 element\n",
          folder.path() + ": usable as a layout, 0 layout warnings - 1 page\n"})
        EXPECT_NE(outcome.out.find(line), std::string::npos) << line << "\n" << outcome.out;
    EXPECT_EQ(outcome.out.find("config/gleisbild.cs2:"), std::string::npos)
        << "the missing file is not checked";
}

TEST(Cs2CheckFolder, AnUnusableFileMakesTheFolderUnusable) {
    ScratchFolder folder;
    folder.add("gleisbild.cs2", "[gleisbild]\nseite\n .id=1\n .name=Bahnhof\n");
    folder.add("gleisbilder/Bahnhof.cs2", "[conf]\nelement\n .id=1\n");
    const Outcome outcome = cs2Command({"check", folder.path()});
    EXPECT_EQ(outcome.status, 1) << outcome.out;
    EXPECT_NE(outcome.out.find(folder.path() + ": not usable as a layout"), std::string::npos) << outcome.out;
}

} // namespace
