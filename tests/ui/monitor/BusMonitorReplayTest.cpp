// Playing a candump log back: order, count, original timing scaled by the speed factor, pause, and lines
// that hold no frame.

#include "monitor/BusMonitorReplay.h"

#include "EmbeddedStationSupport.h"
#include "can/FrameText.h"
#include "connection/StationConnection.h"
#include "monitor/BusMonitorModel.h"
#include "monitor/BusMonitorPanel.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <gtest/gtest.h>
#include <utility>
#include <vector>

using namespace stellwerk;
using namespace stellwerk::ui;
using ReplayState = BusMonitorReplay::State;

namespace {

constexpr int ReplayMs = 10000;

// A log with frames at 0, 0.1 s (two at once), 0.2 s (marked T, sent) and `lastAt`, and lines
// without a frame.
QByteArray timedLog(const char* lastAt = "1700000001.000000") {
    return QByteArray("# recorded by a test\n"
                      "(1700000000.000000) can0 00004711#0000000000\n"
                      "(1700000000.100000) can0 00084711#0000C0030120\n"
                      "(1700000000.100000) can0 00084711#0000C0030121\n"
                      "this is not a frame\n"
                      "\n"
                      "(1700000000.200000) can0 000A4711#0000C00301 T\n"
                      "(1700000000.250000) can0 00084711#XYZ\n"
                      "(") +
           lastAt + ") can0 00024711#0000000001\n";
}

// What a replay delivered: each frame with the time it carried and when (since start) it arrived.
struct Arrivals {
    explicit Arrivals(BusMonitorReplay& replay) {
        clock.start();
        QObject::connect(
            &replay, &BusMonitorReplay::framesReplayed, &context,
            [this](const std::vector<can::CanFrame>& frames, const QDateTime& time, bool outgoing, int) {
                ++batches;
                for (const can::CanFrame& frame : frames) {
                    texts.push_back(can::formatCandump(frame));
                    times.push_back(time.toMSecsSinceEpoch());
                    arrivedMs.push_back(clock.elapsed());
                    sent.push_back(outgoing);
                }
            });
        QObject::connect(&replay, &BusMonitorReplay::lineSkipped, &context,
                         [this](int line, const QString&) { skippedLines.push_back(line); });
    }

    QObject context;
    QElapsedTimer clock;
    int batches = 0;
    std::vector<std::string> texts;
    std::vector<qint64> times;
    std::vector<qint64> arrivedMs;
    std::vector<bool> sent;
    std::vector<int> skippedLines;
};

class BusMonitorReplayTest : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_TRUE(dir.isValid()); }
    QString write(const QByteArray& content) {
        const QString path = dir.filePath(QStringLiteral("bus.log"));
        QFile file(path);
        EXPECT_TRUE(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(content);
        return path;
    }
    bool waitUntilFinished(const BusMonitorReplay& replay) {
        return QTest::qWaitFor([&] { return replay.state() == ReplayState::Finished; }, ReplayMs);
    }

    QTemporaryDir dir;
};

const std::vector<std::string> expectedFrames{"00004711#0000000000", "00084711#0000C0030120",
                                              "00084711#0000C0030121", "000A4711#0000C00301",
                                              "00024711#0000000001"};

} // namespace

TEST_F(BusMonitorReplayTest, DeliversEveryFrameInOrderWithItsLogTimeAndSkipsBadLines) {
    BusMonitorReplay replay;
    Arrivals arrivals(replay);
    QSignalSpy progress(&replay, &BusMonitorReplay::progressChanged);
    replay.setSpeed(BusMonitorReplay::AsFastAsPossible);
    ASSERT_EQ(replay.start(write(timedLog())), QString());
    ASSERT_TRUE(waitUntilFinished(replay));
    EXPECT_EQ(arrivals.texts, expectedFrames);
    EXPECT_EQ(arrivals.times, (std::vector<qint64>{1700000000000, 1700000000100, 1700000000100, 1700000000200,
                                                   1700000001000}));
    EXPECT_EQ(arrivals.batches, 4) << "the two frames of one time stamp come as one batch";
    EXPECT_EQ(arrivals.sent, (std::vector<bool>{false, false, false, true, false})) << "T marks a sent frame";
    EXPECT_EQ(arrivals.skippedLines, (std::vector<int>{5, 8}));
    EXPECT_EQ(replay.framesPlayed(), 5);
    EXPECT_EQ(replay.linesSkipped(), 2);
    ASSERT_FALSE(progress.isEmpty());
    EXPECT_EQ(progress.last().at(0).toInt(), 100);
    EXPECT_EQ(replay.percent(), 100);
}

// At 2x the last frame, 3 s after the first in the log, comes no sooner than 1.5 s after it, and after
// all the others; at 10x it comes 0.3 s after the first.
TEST_F(BusMonitorReplayTest, KeepsTheLogsTimingScaledBySpeed) {
    const QString path = write(timedLog("1700000003.000000"));
    BusMonitorReplay twice;
    Arrivals slow(twice);
    twice.setSpeed(2.0);
    ASSERT_EQ(twice.start(path), QString());
    ASSERT_TRUE(QTest::qWaitFor([&] { return slow.texts.size() >= 4; }, ReplayMs));
    EXPECT_LT(slow.texts.size(), 5u) << "the last frame is due 1.5 s after the first";
    ASSERT_TRUE(waitUntilFinished(twice));
    EXPECT_EQ(slow.texts, expectedFrames);
    EXPECT_GE(slow.arrivedMs.back() - slow.arrivedMs.front(), 1500 - 5);
    for (std::size_t i = 1; i < slow.arrivedMs.size(); ++i)
        EXPECT_LE(slow.arrivedMs[i - 1], slow.arrivedMs[i]);

    BusMonitorReplay tenTimes;
    Arrivals fast(tenTimes);
    tenTimes.setSpeed(10.0);
    ASSERT_EQ(tenTimes.start(path), QString());
    ASSERT_TRUE(waitUntilFinished(tenTimes));
    EXPECT_EQ(fast.texts, expectedFrames);
    EXPECT_GE(fast.arrivedMs.back() - fast.arrivedMs.front(), 300 - 5);
}

TEST_F(BusMonitorReplayTest, AsFastAsPossibleIgnoresAnHourLongGap) {
    BusMonitorReplay replay;
    Arrivals arrivals(replay);
    replay.setSpeed(BusMonitorReplay::AsFastAsPossible);
    ASSERT_EQ(replay.start(write(timedLog("1700003600.000000"))), QString());
    ASSERT_TRUE(waitUntilFinished(replay));
    EXPECT_EQ(arrivals.texts, expectedFrames);
}

TEST_F(BusMonitorReplayTest, PauseHoldsTheRestBackUntilResumeAndStopEndsIt) {
    BusMonitorReplay replay;
    Arrivals arrivals(replay);
    QSignalSpy states(&replay, &BusMonitorReplay::stateChanged);
    ASSERT_EQ(replay.start(write(timedLog())), QString());
    ASSERT_TRUE(QTest::qWaitFor([&] { return !arrivals.texts.empty(); }, ReplayMs));
    replay.pause();
    EXPECT_EQ(replay.state(), ReplayState::Paused);
    const std::size_t before = arrivals.texts.size();
    QTest::qWait(1200); // longer than the whole log
    EXPECT_EQ(arrivals.texts.size(), before);
    replay.resume();
    ASSERT_TRUE(waitUntilFinished(replay));
    EXPECT_EQ(arrivals.texts, expectedFrames);

    ASSERT_EQ(replay.start(write(timedLog())), QString());
    ASSERT_TRUE(QTest::qWaitFor([&] { return arrivals.texts.size() > expectedFrames.size(); }, ReplayMs));
    replay.stop();
    const std::size_t stopped = arrivals.texts.size();
    QTest::qWait(1200);
    EXPECT_EQ(arrivals.texts.size(), stopped);
    EXPECT_EQ(replay.state(), ReplayState::Idle);
    EXPECT_GE(states.count(), 5); // playing, paused, playing, finished, playing, idle
}

// candump writes six digits after the point; fewer are read as a decimal fraction, none as whole seconds.
TEST_F(BusMonitorReplayTest, TimeStampsWithFewerDigitsAreReadAsFractions) {
    BusMonitorReplay replay;
    Arrivals arrivals(replay);
    replay.setSpeed(BusMonitorReplay::AsFastAsPossible);
    ASSERT_EQ(replay.start(write("(1700000000.5) can0 00004711#0000000000\n"
                                 "(1700000001) vcan0 00004711#0000000001\n"
                                 "00004711 5 00 00 00 00 00\n")),
              QString());
    ASSERT_TRUE(waitUntilFinished(replay));
    ASSERT_EQ(arrivals.times.size(), 3u);
    EXPECT_EQ(arrivals.times[0], 1700000000500);
    EXPECT_EQ(arrivals.times[1], 1700000001000);
    EXPECT_EQ(arrivals.times[2], 1700000001000) << "a line without a stamp has the time of the one before";
    EXPECT_TRUE(arrivals.skippedLines.empty());

    BusMonitorReplay unstamped;
    Arrivals now(unstamped);
    const qint64 started = QDateTime::currentMSecsSinceEpoch();
    ASSERT_EQ(unstamped.start(write("00004711 5 00 00 00 00 00\n")), QString());
    ASSERT_TRUE(waitUntilFinished(unstamped));
    ASSERT_EQ(now.times.size(), 1u);
    EXPECT_GE(now.times[0], started) << "without any stamp, frames show when they were played";
}

TEST_F(BusMonitorReplayTest, AMissingFileIsAnErrorAndNothingPlays) {
    BusMonitorReplay replay;
    EXPECT_FALSE(replay.start(dir.filePath(QStringLiteral("missing.log"))).isEmpty());
    EXPECT_EQ(replay.state(), ReplayState::Idle);
}

// The panel: a replay fills the table in the log's order with the log's times, and live frames wait
// outside while it plays.
TEST_F(BusMonitorReplayTest, PanelShowsTheReplayedFramesInsteadOfLiveOnes) {
    connection::StationConnection station{support::withEmbeddedStation()};
    BusMonitorPanel panel;
    panel.setBuses(&station.buses());
    panel.setReplaySpeed(10.0);
    ASSERT_EQ(panel.openLog(write(timedLog())), QString());
    emit station.buses().busFramesSeen(0, {can::parseFrame("00004711 5 00 00 00 00 01").value().frame},
                                       false);
    ASSERT_TRUE(QTest::qWaitFor([&] { return panel.replay()->state() == ReplayState::Finished; }, ReplayMs));
    panel.model()->flush();
    const BusMonitorModel& model = *panel.model();
    ASSERT_EQ(model.rowCount(), 5);
    for (int row = 0; row < 5; ++row)
        EXPECT_EQ(can::formatCandump(model.frameAt(row)), expectedFrames[std::size_t(row)]);
    EXPECT_EQ(model.timeAt(4).toMSecsSinceEpoch(), 1700000001000);
    EXPECT_EQ(model.directionAt(3), BusMonitorModel::Direction::Sent);
    EXPECT_EQ(model.directionAt(4), BusMonitorModel::Direction::Received);
}
