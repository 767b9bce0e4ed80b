// The locomotives' pictures: from the station's web server (the embedded station and a fake one that
// breaks on purpose), from an icons folder, with the limits, the faults and the station coming back.

#include "connection/LocomotivePictures.h"

#include "EmbeddedStationSupport.h"
#include "FakeWebServer.h"
#include "SimProgram.h"
#include "connection/StationConnection.h"
#include "sim/EmbeddedStation.h"
#include "sim/StationLayout.h"

#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>
#include <gtest/gtest.h>

namespace stellwerk::connection::test {
namespace {

using Status = LocomotivePictures::Status;
using support::FakeWebServer;
using namespace std::chrono_literals;

constexpr int WaitMs = 10000;

QByteArray demoPicture(const char* name) {
    static const sim::StationLayout demo = sim::StationLayout::demo();
    return QByteArray::fromStdString(demo.pictureFor(name).value_or(std::string()));
}

bool settled(LocomotivePictures& pictures, const QString& icon, int timeoutMs = WaitMs) {
    pictures.picture(icon);
    return QTest::qWaitFor([&] { return pictures.status(icon) != Status::Loading; }, timeoutMs);
}

LocomotivePictures::Settings quick() {
    LocomotivePictures::Settings settings;
    settings.timeout = 500ms;
    return settings;
}

class PicturesFromAStation : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_FALSE(demoPicture("BR 218.png").isEmpty());
        web_.add("BR 218.png", demoPicture("BR 218.png"));
        web_.add("ICE 3.png", demoPicture("ICE 3.png"));
        pictures_.setStation(web_.address());
    }

    FakeWebServer web_;
    LocomotivePictures pictures_{quick()};
};

TEST(LocomotivePictures, TheEmbeddedStationServesItsDemoPictures) {
    sim::EmbeddedStation station;
    ASSERT_TRUE(station.start());
    LocomotivePictures pictures;
    pictures.setStation(station.webAddress());
    QSignalSpy changed(&pictures, &LocomotivePictures::picturesChanged);
    EXPECT_EQ(pictures.picture("BR 218"), std::nullopt);
    EXPECT_EQ(pictures.status("BR 218"), Status::Loading);
    ASSERT_TRUE(settled(pictures, "BR 218"));
    EXPECT_EQ(pictures.picture("BR 218"), demoPicture("BR 218.png"));
    EXPECT_EQ(pictures.source("BR 218"), station.webAddress() + "/icons/BR%20218.png");
    EXPECT_GE(changed.count(), 1);
}

TEST_F(PicturesFromAStation, APictureIsFetchedOnceAndKept) {
    ASSERT_TRUE(settled(pictures_, "BR 218"));
    EXPECT_EQ(pictures_.status("BR 218"), Status::Present);
    for (int i = 0; i < 3; ++i)
        EXPECT_EQ(pictures_.picture("BR 218"), demoPicture("BR 218.png"));
    EXPECT_EQ(web_.requests(), 1);
}

TEST_F(PicturesFromAStation, APictureTheStationLacksIsMissingAndNotAskedForAgain) {
    ASSERT_TRUE(settled(pictures_, "BR 86"));
    EXPECT_EQ(pictures_.status("BR 86"), Status::Missing);
    EXPECT_EQ(pictures_.problem("BR 86"), "the station has no picture BR 86.png");
    EXPECT_EQ(pictures_.reason("BR 86"), LocomotivePictures::Reason::NotThere);
    pictures_.retryFailed();
    EXPECT_EQ(pictures_.picture("BR 86"), std::nullopt);
    EXPECT_EQ(pictures_.status("BR 86"), Status::Missing);
    EXPECT_EQ(web_.requests(), 1);
}

TEST_F(PicturesFromAStation, ACs3PathAsksForItsLastSegment) {
    web_.add("mSD3_Logo.png", demoPicture("V 100.png"));
    ASSERT_TRUE(settled(pictures_, "/usr/local/cs3/lokicons/mSD3_Logo"));
    EXPECT_EQ(pictures_.picture("/usr/local/cs3/lokicons/mSD3_Logo"), demoPicture("V 100.png"));
}

TEST_F(PicturesFromAStation, ANameThatCouldLeaveTheFolderIsNeverAskedFor) {
    EXPECT_EQ(pictures_.picture("../../etc/passwd#"), std::nullopt);
    EXPECT_EQ(pictures_.status("../../etc/passwd#"), Status::Missing);
    EXPECT_EQ(pictures_.problem("../../etc/passwd#"), "\"../../etc/passwd#\" names no usable picture file");
    EXPECT_EQ(pictures_.problem(""), "the locomotive names no picture");
    EXPECT_EQ(pictures_.reason(""), LocomotivePictures::Reason::NoName);
    QTest::qWait(100);
    EXPECT_EQ(web_.requests(), 0);
}

TEST_F(PicturesFromAStation, GarbageFromTheStationIsNoPictureAndSaysSo) {
    web_.setMode(FakeWebServer::Mode::Html);
    ASSERT_TRUE(settled(pictures_, "BR 218"));
    EXPECT_EQ(pictures_.status("BR 218"), Status::Missing);
    EXPECT_EQ(pictures_.problem("BR 218"), "the station's BR 218.png is not a PNG picture");
    EXPECT_EQ(pictures_.reason("BR 218"), LocomotivePictures::Reason::NotAPicture);

    web_.setMode(FakeWebServer::Mode::Garbage);
    ASSERT_TRUE(settled(pictures_, "ICE 3"));
    EXPECT_EQ(pictures_.status("ICE 3"), Status::Failed);
    EXPECT_TRUE(pictures_.problem("ICE 3").startsWith("ICE 3.png could not be fetched: "))
        << pictures_.problem("ICE 3").toStdString();
    EXPECT_EQ(pictures_.picture("ICE 3"), std::nullopt);
    EXPECT_EQ(pictures_.reason("ICE 3"), LocomotivePictures::Reason::Unreachable);
}

TEST_F(PicturesFromAStation, AHugeAnswerIsCutOffAtTheLimit) {
    web_.setMode(FakeWebServer::Mode::Huge);
    ASSERT_TRUE(settled(pictures_, "BR 218"));
    EXPECT_EQ(pictures_.status("BR 218"), Status::Missing);
    EXPECT_EQ(pictures_.problem("BR 218"), "the station's BR 218.png is larger than 262144 bytes");
}

TEST_F(PicturesFromAStation, ASilentStationTimesOutAndIsAskedAgainWhenBack) {
    web_.setMode(FakeWebServer::Mode::Silent);
    ASSERT_TRUE(settled(pictures_, "BR 218", 3000));
    EXPECT_EQ(pictures_.status("BR 218"), Status::Failed);
    web_.setMode(FakeWebServer::Mode::Serve);
    pictures_.retryFailed();
    ASSERT_TRUE(settled(pictures_, "BR 218"));
    EXPECT_EQ(pictures_.picture("BR 218"), demoPicture("BR 218.png"));
}

TEST_F(PicturesFromAStation, AtMostTwoFetchesRunAtOnce) {
    for (const char* name : {"A", "B", "C", "D", "E", "BR 218"})
        pictures_.picture(name);
    ASSERT_TRUE(QTest::qWaitFor([&] { return pictures_.status("BR 218") == Status::Present; }, WaitMs));
    EXPECT_EQ(web_.requests(), 6);
    EXPECT_LE(web_.mostAtOnce(), 2);
    EXPECT_EQ(pictures_.status("C"), Status::Missing);
}

// The station is switched off while it sends a picture and comes back after 1 s or 20 s: the cut
// picture is never shown, nothing is asked for while it is away, and the picture arrives once the
// connection's start-up found the station again (retryFailed).
class StationGoneMidPicture : public PicturesFromAStation, public ::testing::WithParamInterface<int> {};

TEST_P(StationGoneMidPicture, TheCutPictureIsNeverShownAndTheWholeOneComesWhenBack) {
    web_.setMode(FakeWebServer::Mode::CutMidBody);
    ASSERT_TRUE(settled(pictures_, "BR 218"));
    EXPECT_EQ(pictures_.status("BR 218"), Status::Failed);
    EXPECT_EQ(pictures_.picture("BR 218"), std::nullopt);
    web_.stop();
    QTest::qWait(GetParam());
    EXPECT_EQ(pictures_.picture("BR 218"), std::nullopt) << "asked again before retryAfter";
    EXPECT_EQ(pictures_.status("BR 218"), Status::Failed);
    EXPECT_EQ(web_.requests(), 1);

    web_.setMode(FakeWebServer::Mode::Serve);
    ASSERT_TRUE(web_.start());
    pictures_.retryFailed();
    ASSERT_TRUE(settled(pictures_, "BR 218"));
    EXPECT_EQ(pictures_.picture("BR 218"), demoPicture("BR 218.png"));
    EXPECT_EQ(web_.requests(), 2);
}

INSTANTIATE_TEST_SUITE_P(BackAfter, StationGoneMidPicture, ::testing::Values(1000, 20000),
                         [](const auto& info) { return std::to_string(info.param / 1000) + "s"; });

TEST(LocomotivePictures, AFailedFetchIsTriedAgainAfterRetryAfter) {
    FakeWebServer web;
    web.add("BR 218.png", demoPicture("BR 218.png"));
    web.stop();
    LocomotivePictures::Settings settings = quick();
    settings.retryAfter = 300ms;
    LocomotivePictures pictures(settings);
    pictures.setStation(web.address());
    ASSERT_TRUE(settled(pictures, "BR 218"));
    EXPECT_EQ(pictures.status("BR 218"), Status::Failed);
    EXPECT_TRUE(pictures.problem("BR 218").contains("refused")) << pictures.problem("BR 218").toStdString();
    ASSERT_TRUE(web.start());
    QTest::qWait(400);
    ASSERT_TRUE(settled(pictures, "BR 218"));
    EXPECT_EQ(pictures.status("BR 218"), Status::Present);
}

// Two programs on the same station (this one twice) fetch the same pictures at the same time.
TEST(LocomotivePictures, TwoProgramsFetchingFromOneStationBothGetThem) {
    sim::EmbeddedStation station;
    ASSERT_TRUE(station.start());
    LocomotivePictures first;
    LocomotivePictures second;
    first.setStation(station.webAddress());
    second.setStation(station.webAddress());
    const QStringList icons{"BR 218", "ICE 3", "BR 01", "Taurus"};
    for (const QString& icon : icons) {
        first.picture(icon);
        second.picture(icon);
    }
    for (const QString& icon : icons) {
        ASSERT_TRUE(settled(first, icon));
        ASSERT_TRUE(settled(second, icon));
        EXPECT_EQ(first.picture(icon), second.picture(icon));
        EXPECT_EQ(first.status(icon), Status::Present) << first.problem(icon).toStdString();
    }
}

TEST(LocomotivePictures, TheLayoutsIconsFolderComesBeforeTheStation) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    QFile own(QDir(dir.path()).filePath("BR 218.png"));
    ASSERT_TRUE(own.open(QIODevice::WriteOnly));
    own.write(demoPicture("E 44.png"));
    own.close();
    QFile damaged(QDir(dir.path()).filePath("ICE 3.png"));
    ASSERT_TRUE(damaged.open(QIODevice::WriteOnly));
    damaged.write(demoPicture("ICE 3.png").left(100));
    damaged.close();

    FakeWebServer web;
    web.add("BR 01.png", demoPicture("BR 01.png"));
    LocomotivePictures pictures(quick());
    pictures.setStation(web.address());
    pictures.setFolder(dir.path());
    EXPECT_EQ(pictures.picture("BR 218"), demoPicture("E 44.png")) << "read from the folder at once";
    EXPECT_EQ(pictures.source("BR 218"), own.fileName());
    EXPECT_EQ(pictures.status("ICE 3"), Status::Unknown);
    EXPECT_EQ(pictures.picture("ICE 3"), std::nullopt);
    EXPECT_EQ(pictures.status("ICE 3"), Status::Missing);
    EXPECT_EQ(pictures.problem("ICE 3"), damaged.fileName() + ": a cut-off PNG picture (no IEND at its end)");
    ASSERT_TRUE(settled(pictures, "BR 01"));
    EXPECT_EQ(pictures.picture("BR 01"), demoPicture("BR 01.png")) << "not in the folder: from the station";
    EXPECT_EQ(web.requests(), 1);
}

TEST(LocomotivePictures, WithoutFolderOrStationAPictureIsMissing) {
    LocomotivePictures pictures;
    EXPECT_EQ(pictures.picture("BR 218"), std::nullopt);
    EXPECT_EQ(pictures.status("BR 218"), Status::Missing);
    EXPECT_EQ(pictures.problem("BR 218"), "no icons folder has BR 218.png and no station to ask");
    EXPECT_EQ(pictures.reason("BR 218"), LocomotivePictures::Reason::NoSource);
}

TEST_F(PicturesFromAStation, AMissingPictureSaysWhereItWasLookedFor) {
    ASSERT_TRUE(settled(pictures_, "BR 86"));
    EXPECT_EQ(pictures_.status("BR 86"), Status::Missing);
    EXPECT_EQ(pictures_.lookedAt("BR 86"), web_.address() + "/icons/BR%2086.png");
    EXPECT_EQ(pictures_.source("BR 86"), "") << "the source is where a picture came from";
}

TEST(LocomotivePictures, WithoutAStationTheIconsFolderIsWhereItWasLookedFor) {
    QTemporaryDir icons;
    LocomotivePictures pictures;
    pictures.setFolder(icons.path());
    EXPECT_EQ(pictures.picture("BR 218"), std::nullopt);
    EXPECT_EQ(pictures.lookedAt("BR 218"), QDir(icons.path()).filePath("BR 218.png"));
}

// Issue 32: a station whose web server is not on port 80 (a simulator started with --http-port 8080, a
// gateway) is named with `?http=<port>` after its address; the pictures come from that port.
TEST(StationConnectionPictures, AnAddressWithAnHttpPortFetchesThePicturesThere) {
    FakeWebServer web;
    web.add("ICE 3.png", demoPicture("ICE 3.png"));
    const QString port = web.address().section(QLatin1Char(':'), -1);
    StationConnection connection(support::withEmbeddedStation());
    connection.connectTo("tcp://127.0.0.1:1?http=" + port);
    EXPECT_EQ(connection.pictures().station(), web.address());
    EXPECT_EQ(connection.endpoint().description(), QStringLiteral("CS2 at 127.0.0.1:1 (TCP)"));
    ASSERT_TRUE(settled(connection.pictures(), "ICE 3"));
    EXPECT_EQ(connection.pictures().picture("ICE 3"), demoPicture("ICE 3.png"));
    EXPECT_EQ(web.requests(), 1);
    connection.connectTo("udp://127.0.0.1?listen=0&http=" + port);
    EXPECT_EQ(connection.pictures().station(), web.address());
    connection.connectTo("tcp://127.0.0.1:1?http=80");
    EXPECT_EQ(connection.pictures().station(), "http://127.0.0.1");
}

// stellwerk-sim serves the pictures on its --http-port and says which address to give Stellwerk for them;
// through that address they come from the simulator.
TEST(StationConnectionPictures, StellwerkSimSaysTheAddressThroughWhichItsPicturesLoad) {
    QTcpServer probe;
    ASSERT_TRUE(probe.listen(QHostAddress::LocalHost, 0));
    const std::uint16_t http = probe.serverPort();
    probe.close();
    support::SimProgram sim({"--listen", "127.0.0.1", "--udp-port", "0", "--udp-reply-host", "127.0.0.1",
                             "--tcp-port", "0", "--http-port", QString::number(http), "--no-trains"});
    ASSERT_TRUE(sim.printed("station address for Stellwerk")) << sim.output().toStdString();
    const QRegularExpression said(QStringLiteral(
        "station address for Stellwerk \\(with the pictures\\): (tcp://127\\.0\\.0\\.1:\\d+\\?http=(\\d+))"));
    const QRegularExpressionMatch match = said.match(sim.output());
    ASSERT_TRUE(match.hasMatch()) << sim.output().toStdString();
    EXPECT_EQ(match.captured(2).toUInt(), http);
    StationConnection connection(support::withEmbeddedStation());
    connection.connectTo(match.captured(1));
    EXPECT_EQ(connection.pictures().station(), QStringLiteral("http://127.0.0.1:%1").arg(http));
    ASSERT_TRUE(settled(connection.pictures(), "BR 218"));
    EXPECT_EQ(connection.pictures().status("BR 218"), Status::Present)
        << connection.pictures().problem("BR 218").toStdString();
}

TEST(StationConnectionPictures, TheWebAddressFollowsTheStation) {
    StationConnection connection(support::withEmbeddedStation());
    connection.connectTo("tcp://127.0.0.1:1");
    EXPECT_EQ(connection.pictures().station(), "http://127.0.0.1");
    connection.connectTo("udp://192.168.2.5");
    EXPECT_EQ(connection.pictures().station(), "http://192.168.2.5");
    connection.connectTo("can://virtualcan/can0");
    EXPECT_EQ(connection.pictures().station(), "");
    connection.connectToSimulator();
    EXPECT_TRUE(connection.pictures().station().startsWith("http://127.0.0.1:"));
    ASSERT_TRUE(settled(connection.pictures(), "ICE 3"));
    EXPECT_EQ(connection.pictures().picture("ICE 3"), demoPicture("ICE 3.png"));
    connection.disconnectFromStation();
    EXPECT_EQ(connection.pictures().station(), "");
}

} // namespace
} // namespace stellwerk::connection::test
