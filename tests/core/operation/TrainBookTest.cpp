// The book of trains kept beside the layout: written on every change, read again after a restart, and a
// damaged file put aside with a sentence, never overwritten or lost.

#include "operation/TrainBook.h"

#include "model/LayoutInUse.h"
#include "operation/TrainBookFile.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <gtest/gtest.h>

namespace stellwerk::operation {
namespace {

BookedTrain scheduledTrain() {
    BookedTrain train;
    train.locId = 0x4001;
    train.lengthMm = 340;
    train.pushPull = true;
    train.block = "Gleis 1";
    train.blockId = 4;
    train.towards = trackgraph::End::A;
    train.automatic = true;
    train.schedule.loop = true;
    train.schedule.next = 1;
    train.schedule.pushPull = true;
    train.schedule.stops = {{"Gleis 2", 5000, 0}, {"Block 3", 1500, 0}};
    return train;
}

std::filesystem::path pathIn(const QTemporaryDir& dir, const char* name) {
    return std::filesystem::path(dir.path().toStdString()) / name;
}

TEST(TrainBook, SavedAndReadAgainIsTheSameBook) {
    QTemporaryDir dir;
    TrainBook book;
    book.put(scheduledTrain());
    BookedTrain manual;
    manual.locId = 0x18;
    manual.block = "Gleis 2";
    manual.blockId = 1;
    book.put(manual);
    const TrainBookFile file(pathIn(dir, "trains/book.json"));
    EXPECT_EQ(file.save(book), "");

    TrainBookFile again(file.path());
    std::string problem;
    const TrainBook read = again.load(problem);
    EXPECT_EQ(problem, "");
    ASSERT_EQ(read.trains().size(), 2u);
    EXPECT_EQ(read.toJson(), book.toJson());
    EXPECT_EQ(read.find(0x4001)->schedule.stops[1].dwellMs, 1500);
    EXPECT_EQ(read.find(0x4001)->schedule.next, 1u);
    EXPECT_EQ(read.find(0x18)->lengthMm, 200); // the default length
}

TEST(TrainBook, PutReplacesTheSameLocomotiveAndRemoveTakesItOut) {
    TrainBook book;
    book.put(scheduledTrain());
    BookedTrain moved = scheduledTrain();
    moved.block = "Block 4";
    book.put(moved);
    ASSERT_EQ(book.trains().size(), 1u);
    EXPECT_EQ(book.find(0x4001)->block, "Block 4");
    book.remove(0x4001);
    EXPECT_TRUE(book.empty());
}

TEST(TrainBook, AMissingFileIsAnEmptyBookWithoutProblem) {
    QTemporaryDir dir;
    TrainBookFile file(pathIn(dir, "none.json"));
    std::string problem = "before";
    EXPECT_TRUE(file.load(problem).empty());
    EXPECT_EQ(problem, "");
}

// A damaged book: a clear sentence, the file kept aside under another name with its bytes, and the next
// save writes a new book without touching the kept one.
TEST(TrainBook, ADamagedFileIsPutAsideWithASentenceAndNothingIsLost) {
    QTemporaryDir dir;
    const std::filesystem::path path = pathIn(dir, "book.json");
    const QByteArray damaged = R"({"version": 1, "trains": [{"loc": 16385, "block": "Gleis 1")";
    {
        QFile out(QString::fromStdString(path.string()));
        ASSERT_TRUE(out.open(QIODevice::WriteOnly));
        out.write(damaged);
    }
    TrainBookFile file(path);
    std::string problem;
    EXPECT_TRUE(file.load(problem).empty());
    EXPECT_NE(problem.find("is damaged"), std::string::npos) << problem;
    EXPECT_NE(problem.find("kept as"), std::string::npos) << problem;
    const QStringList aside = QDir(dir.path()).entryList({QStringLiteral("book.json.unreadable-*")});
    ASSERT_EQ(aside.size(), 1) << problem;
    EXPECT_NE(problem.find(aside.front().toStdString()), std::string::npos) << problem;
    EXPECT_FALSE(std::filesystem::exists(path));

    TrainBook book;
    book.put(scheduledTrain());
    EXPECT_EQ(file.save(book), "");
    QFile kept(dir.filePath(aside.front()));
    ASSERT_TRUE(kept.open(QIODevice::ReadOnly));
    EXPECT_EQ(kept.readAll(), damaged);
}

TEST(TrainBook, WrongContentSaysWhatIsWrong) {
    EXPECT_FALSE(TrainBook::fromJson("[1, 2]"));
    const auto facing = TrainBook::fromJson(R"({"trains": [{"loc": 1, "towards": "c"}]})");
    ASSERT_FALSE(facing);
    EXPECT_NE(facing.error().find("\"c\""), std::string::npos);
    const auto noLoc = TrainBook::fromJson(R"({"trains": [{"block": "Gleis 1"}]})");
    ASSERT_FALSE(noLoc);
    EXPECT_NE(noLoc.error().find("locomotive"), std::string::npos);
    const auto newer = TrainBook::fromJson(R"({"version": 7, "trains": []})");
    ASSERT_FALSE(newer);
    EXPECT_NE(newer.error().find("newer"), std::string::npos);
}

// A station's book lives in the data folder under the station's name; an opened folder's beside it.
TEST(TrainBook, KeptInTheDataFolderForAStationAndBesideAnOpenedFolder) {
    QTemporaryDir dir;
    const std::filesystem::path data = pathIn(dir, "data");
    model::LayoutInUse layout;
    EXPECT_TRUE(TrainBookFile::placeFor(layout, data, "").empty());
    const std::filesystem::path layoutFolder = pathIn(dir, "my-layout");
    std::filesystem::create_directories(layoutFolder / "config");
    std::filesystem::copy(STELLWERK_DEMO_LAYOUT_DIR, layoutFolder / "config",
                          std::filesystem::copy_options::recursive);
    ASSERT_EQ(layout.open(layoutFolder), "");
    EXPECT_EQ(TrainBookFile::placeFor(layout, data, "tcp://192.168.2.5"),
              layoutFolder / "stellwerk-trains.json");
    layout.forgetStation();
}

TEST(TrainBook, AStationsBookIsNamedAfterTheStation) {
    model::LayoutInUse layout;
    station::StartupResult result;
    layout.useStationDownload(result);
    if (layout.origin() != model::LayoutInUse::Origin::Station)
        GTEST_SKIP() << "an empty download is no layout";
    EXPECT_EQ(TrainBookFile::placeFor(layout, "/data", "tcp://192.168.2.5"),
              std::filesystem::path("/data/trains/station-tcp---192-168-2-5.json"));
    EXPECT_EQ(TrainBookFile::placeFor(layout, "/data", ""),
              std::filesystem::path("/data/trains/station-simulated.json"));
}

} // namespace
} // namespace stellwerk::operation
