#include "EmbeddedStationSupport.h"
#include "binding/RailwayBinding.h"
#include "can/FrameText.h"
#include "model/Railway.h"
#include "monitor/BusMonitorModel.h"
#include "monitor/BusMonitorPanel.h"
#include "monitor/BusMonitorReplay.h"
#include "shell/Translations.h"
#include "support/MonitorTestSupport.h"
#include "support/StationTestSupport.h"

#include <QAbstractItemModel>
#include <QColor>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <cstdlib>
#include <gtest/gtest.h>
#include <vector>

using namespace stellwerk;
using namespace stellwerk::ui;
using Direction = BusMonitorModel::Direction;
using test::cell;
using test::frame;
using test::systemStop;

namespace {

// The demo trains pass a contact every second or two; generous for a loaded machine.
constexpr int FramesMs = 10000;

constexpr quint32 V100 = 0x18; // V 100 2023, MM2 address 24: stands still in the demo

// loco.speed for Loc-ID 0xC003 (DCC 3), speed 288, as in the protocol document.
can::CanFrame locoSpeed() {
    return frame("00084711 6 00 00 C0 03 01 20");
}
} // namespace

TEST(BusMonitorModel, TenThousandFramesInOneBatchAreOneInsertion) {
    BusMonitorModel model;
    QSignalSpy inserted(&model, &QAbstractItemModel::rowsInserted);
    const std::vector<can::CanFrame> frames(10000, locoSpeed());
    model.addFrames(frames, Direction::Received);
    EXPECT_EQ(model.rowCount(), 0); // not before the flush
    ASSERT_TRUE(QTest::qWaitFor([&] { return model.rowCount() == 10000; }, 2000));
    EXPECT_EQ(inserted.count(), 1);
    EXPECT_EQ(model.totalFrames(), 10000u);
    EXPECT_EQ(cell(model, 9999, BusMonitorModel::MessageColumn), QStringLiteral("loco.speed"));
    EXPECT_EQ(cell(model, 0, BusMonitorModel::DirectionColumn), QStringLiteral("← received"));
    EXPECT_EQ(cell(model, 0, BusMonitorModel::FrameColumn), QStringLiteral("00084711 6 00 00 C0 03 01 20"));
    EXPECT_TRUE(cell(model, 0, BusMonitorModel::DetailsColumn).contains(QStringLiteral("locId=0xC003")));
}

// Issue 12: a row's columns and roles come from one description; the frame is decoded once.
TEST(BusMonitorModel, ARowIsDecodedOnceForAllItsColumnsAndRoles) {
    BusMonitorModel model;
    const std::vector<can::CanFrame> frames{locoSpeed()};
    model.addFrames(frames, Direction::Received);
    model.flush();
    ASSERT_EQ(model.rowCount(), 1);
    for (int column = 0; column < BusMonitorModel::ColumnCount; ++column)
        for (int role : {int(Qt::DisplayRole), int(Qt::ToolTipRole), int(Qt::BackgroundRole),
                         int(BusMonitorModel::GroupRole), int(BusMonitorModel::CommandRole),
                         int(BusMonitorModel::LocIdRole), int(BusMonitorModel::SearchTextRole)})
            model.index(0, column).data(role);
    EXPECT_EQ(model.commandAt(0), "loco.speed");
    EXPECT_EQ(model.locIdAt(0), 0xC003u);
    EXPECT_TRUE(model.containsText(0, "speed=288"));
    EXPECT_EQ(model.decodeCount(), 1u);
}

// A frame of another protocol is shown as foreign with its 11-bit identifier, never dropped.
TEST(BusMonitorModel, AStandardFrameIsShownAsForeign) {
    BusMonitorModel model;
    const std::vector<can::CanFrame> frames{frame("123#0102")};
    model.addFrames(frames, Direction::Received);
    model.flush();
    ASSERT_EQ(model.rowCount(), 1);
    EXPECT_FALSE(model.frameAt(0).extended);
    EXPECT_EQ(cell(model, 0, BusMonitorModel::MessageColumn), QStringLiteral("foreign"));
    EXPECT_EQ(cell(model, 0, BusMonitorModel::FrameColumn), QStringLiteral("123 2 01 02"));
    EXPECT_EQ(cell(model, 0, BusMonitorModel::DetailsColumn),
              QStringLiteral("11-bit frame (no protocol of a CS2/M-CAN bus)"));
}

TEST(BusMonitorModel, HistoryLimitDropsTheOldestInOneRemoval) {
    BusMonitorModel model;
    model.setHistoryLimit(100);
    const std::vector<can::CanFrame> stops(80, systemStop());
    model.addFrames(stops, Direction::Received);
    model.flush();
    ASSERT_EQ(model.rowCount(), 80);
    QSignalSpy removed(&model, &QAbstractItemModel::rowsRemoved);
    QSignalSpy inserted(&model, &QAbstractItemModel::rowsInserted);
    const std::vector<can::CanFrame> speeds(50, locoSpeed());
    model.addFrames(speeds, Direction::Sent);
    model.flush();
    EXPECT_EQ(model.rowCount(), 100);
    ASSERT_EQ(removed.count(), 1);
    EXPECT_EQ(removed.at(0).at(1).toInt(), 0);
    EXPECT_EQ(removed.at(0).at(2).toInt(), 29); // the 30 oldest
    EXPECT_EQ(inserted.count(), 1);
    EXPECT_EQ(cell(model, 0, BusMonitorModel::MessageColumn), QStringLiteral("system.stop"));
    EXPECT_EQ(cell(model, 49, BusMonitorModel::MessageColumn), QStringLiteral("system.stop"));
    EXPECT_EQ(cell(model, 50, BusMonitorModel::MessageColumn), QStringLiteral("loco.speed"));
    EXPECT_EQ(cell(model, 50, BusMonitorModel::DirectionColumn), QStringLiteral("→ sent"));
    EXPECT_EQ(model.totalFrames(), 130u);

    model.setHistoryLimit(10);
    EXPECT_EQ(model.rowCount(), 10);
    EXPECT_EQ(cell(model, 0, BusMonitorModel::MessageColumn), QStringLiteral("loco.speed"));
}

TEST(BusMonitorModel, PauseHoldsRowsBackAndCountsThem) {
    BusMonitorModel model;
    model.setPaused(true);
    const std::vector<can::CanFrame> frames(25, locoSpeed());
    model.addFrames(frames, Direction::Received);
    model.flush();
    EXPECT_EQ(model.rowCount(), 0);
    EXPECT_EQ(model.heldBack(), 25u);
    EXPECT_EQ(model.totalFrames(), 25u);
    model.setPaused(false);
    EXPECT_EQ(model.rowCount(), 25);
    EXPECT_EQ(model.heldBack(), 0u);
}

TEST(BusMonitorModel, ClearEmptiesRowsQueueAndCounters) {
    BusMonitorModel model;
    model.addFrames(std::vector<can::CanFrame>(5, systemStop()), Direction::Received);
    model.flush();
    model.addFrames(std::vector<can::CanFrame>(5, systemStop()), Direction::Received);
    model.clear();
    EXPECT_EQ(model.rowCount(), 0);
    EXPECT_EQ(model.totalFrames(), 0u);
    model.flush();
    EXPECT_EQ(model.rowCount(), 0);
}

TEST(BusMonitorModel, CommandGroupsHaveDifferentColours) {
    BusMonitorModel model;
    model.addFrames(std::vector<can::CanFrame>{systemStop(), locoSpeed()}, Direction::Received);
    model.flush();
    const QVariant system = model.index(0, 0).data(Qt::BackgroundRole);
    const QVariant loco = model.index(1, 0).data(Qt::BackgroundRole);
    ASSERT_TRUE(system.isValid());
    EXPECT_NE(system.value<QColor>(), loco.value<QColor>());
    EXPECT_EQ(model.index(0, 0).data(BusMonitorModel::GroupRole).toInt(),
              int(BusMonitorModel::Group::System));
    EXPECT_EQ(model.index(1, 0).data(BusMonitorModel::GroupRole).toInt(), int(BusMonitorModel::Group::Loco));
}

TEST(BusMonitorPanel, FilterFindsAFrameByNameAndByLocId) {
    Translations translations;
    ASSERT_TRUE(translations.select(Language::English));
    BusMonitorPanel panel;
    panel.model()->addFrames(std::vector<can::CanFrame>{systemStop(), locoSpeed(), systemStop()},
                             Direction::Received);
    panel.model()->flush();
    const QAbstractItemModel& shown = *panel.table()->model();
    ASSERT_EQ(shown.rowCount(), 3);
    panel.setFilterText(QStringLiteral("loco.SPEED"));
    ASSERT_EQ(shown.rowCount(), 1);
    EXPECT_EQ(cell(shown, 0, BusMonitorModel::MessageColumn), QStringLiteral("loco.speed"));
    panel.setFilterText(QStringLiteral("0xc003"));
    ASSERT_EQ(shown.rowCount(), 1);
    EXPECT_EQ(cell(shown, 0, BusMonitorModel::MessageColumn), QStringLiteral("loco.speed"));
    auto* counter = panel.findChild<QLabel*>(QStringLiteral("busMonitorCounter"));
    ASSERT_NE(counter, nullptr);
    EXPECT_TRUE(counter->text().contains(QStringLiteral("1 row matches the filter")))
        << counter->text().toStdString();
    panel.setFilterText(QString());
    EXPECT_EQ(shown.rowCount(), 3);
}

TEST(BusMonitorPanel, ShowsTheFramesOfTheEmbeddedStation) {
    connection::StationConnection station{support::withEmbeddedStation()};
    BusMonitorPanel panel;
    panel.setBuses(&station.buses());
    station.connectToSimulator();
    ASSERT_TRUE(test::waitForState(station, connection::StationConnection::State::Ready));
    ASSERT_TRUE(QTest::qWaitFor([&] { return panel.model()->rowCount() > 0; }, FramesMs));
    panel.setFilterText(QStringLiteral("feedback.s88-event"));
    const QAbstractItemModel& shown = *panel.table()->model();
    ASSERT_TRUE(QTest::qWaitFor([&] { return shown.rowCount() > 0; }, FramesMs));
    EXPECT_EQ(cell(shown, 0, BusMonitorModel::MessageColumn), QStringLiteral("feedback.s88-event"));
}

// The file holds every batch as soon as it arrived, while recording is still on: a crash keeps it.
TEST(BusMonitorPanel, ARecordingIsOnDiskBatchByBatchWhileItRuns) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("running.log"));
    connection::StationConnection station{support::withEmbeddedStation()};
    BusMonitorPanel recorder;
    recorder.setBuses(&station.buses());
    ASSERT_EQ(recorder.startRecording(path), QString());
    const auto linesOnDisk = [&path] {
        QFile file(path); // a reader of its own, as after a crash
        return file.open(QIODevice::ReadOnly) ? file.readAll().count('\n') : qsizetype(-1);
    };
    emit station.buses().busFramesSeen(0, {systemStop(), locoSpeed()}, false);
    EXPECT_EQ(linesOnDisk(), 2);
    emit station.buses().busFramesSeen(0, {locoSpeed()}, true);
    EXPECT_EQ(linesOnDisk(), 3);
    EXPECT_TRUE(recorder.isRecording());
}

TEST(BusMonitorPanel, RecordsACandumpLogAndOpensItAgain) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("bus.log"));
    connection::StationConnection station{support::withEmbeddedStation()};
    BusMonitorPanel recorder;
    recorder.setBuses(&station.buses());
    ASSERT_EQ(recorder.startRecording(path), QString());
    emit station.buses().busFramesSeen(0, {systemStop(), locoSpeed()}, false);
    emit station.buses().busFramesSeen(0, {locoSpeed()}, true);
    recorder.stopRecording();
    emit station.buses().busFramesSeen(0, {systemStop()}, false); // not recorded any more

    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = file.readAll().split('\n');
    ASSERT_EQ(lines.size(), 4); // three lines and the empty rest after the last newline
    EXPECT_TRUE(lines[1].startsWith('(')) << lines[1].toStdString();
    EXPECT_TRUE(lines[1].endsWith(") can0 00084711#0000C0030120 R")) << lines[1].toStdString();
    EXPECT_TRUE(lines[2].endsWith(") can0 00084711#0000C0030120 T")) << lines[2].toStdString();

    BusMonitorPanel replay;
    replay.setReplaySpeed(BusMonitorReplay::AsFastAsPossible);
    ASSERT_EQ(replay.openLog(path), QString());
    const BusMonitorModel& model = *replay.model();
    ASSERT_TRUE(QTest::qWaitFor([&] { return model.rowCount() == 3; }, FramesMs));
    EXPECT_EQ(cell(model, 0, BusMonitorModel::MessageColumn), QStringLiteral("system.stop"));
    EXPECT_EQ(cell(model, 1, BusMonitorModel::MessageColumn), QStringLiteral("loco.speed"));
    EXPECT_EQ(model.directionAt(1), Direction::Received);
    EXPECT_EQ(model.directionAt(2), Direction::Sent);
    EXPECT_LE(std::abs(model.timeAt(1).msecsTo(QDateTime::currentDateTime())), 60000);
}

TEST(BusMonitorPanel, OpeningALogReportsLinesWithoutAFrame) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("odd.log"));
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write("# a comment\n(1700000000.250000) can0 00004711#0000000000\nnot a frame\n");
    file.close();
    Translations translations;
    ASSERT_TRUE(translations.select(Language::English));
    BusMonitorPanel replay;
    ASSERT_EQ(replay.openLog(path), QString());
    ASSERT_TRUE(QTest::qWaitFor([&] { return replay.replay()->state() == BusMonitorReplay::State::Finished; },
                                FramesMs));
    replay.model()->flush();
    ASSERT_EQ(replay.model()->rowCount(), 1);
    EXPECT_EQ(replay.model()->timeAt(0).toMSecsSinceEpoch(), 1700000000250);
    auto* status = replay.findChild<QLabel*>(QStringLiteral("busMonitorReplayStatus"));
    ASSERT_NE(status, nullptr);
    // "1 line skipped; line 3: ..." once the English plural forms are in translations/stellwerk_en.ts
    EXPECT_TRUE(status->text().startsWith(QStringLiteral("1 line"))) << status->text().toStdString();
    EXPECT_TRUE(status->text().contains(QStringLiteral(" skipped; line 3: 'not' is not")))
        << status->text().toStdString();
    EXPECT_TRUE(status->toolTip().startsWith(QStringLiteral("line 3: 'not' is not")))
        << status->toolTip().toStdString();
    EXPECT_FALSE(replay.findChild<QWidget*>(QStringLiteral("busMonitorReplayBar"))->isHidden());

    replay.backToLive();
    EXPECT_EQ(replay.model()->rowCount(), 0);
    EXPECT_TRUE(replay.findChild<QWidget*>(QStringLiteral("busMonitorReplayBar"))->isHidden());
}

TEST(BusMonitorPanel, AMissingLogIsReportedAndTheLiveViewStays) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    BusMonitorPanel panel;
    connection::StationConnection station{support::withEmbeddedStation()};
    panel.setBuses(&station.buses());
    emit station.buses().busFramesSeen(0, {systemStop()}, false);
    panel.model()->flush();
    ASSERT_EQ(panel.model()->rowCount(), 1);
    EXPECT_FALSE(panel.openLog(dir.filePath(QStringLiteral("none.log"))).isEmpty());
    EXPECT_EQ(panel.replay()->state(), BusMonitorReplay::State::Idle);
    EXPECT_EQ(panel.model()->rowCount(), 1) << "nothing shown is lost";
    EXPECT_TRUE(panel.findChild<QWidget*>(QStringLiteral("busMonitorReplayBar"))->isHidden());
    emit station.buses().busFramesSeen(0, {locoSpeed()}, true);
    panel.model()->flush();
    EXPECT_EQ(panel.model()->rowCount(), 2);
}

// The app's own command on the bus: a speed set through the railway shows as a sent loco.speed for that
// Loc-ID, and the station's answer as a received one; the three filters together find both.
TEST(BusMonitorPanel, ShowsTheCommandsTheAppSendsAndTheAnswers) {
    Translations translations;
    ASSERT_TRUE(translations.select(Language::English));
    test::TestStation simulated;
    ASSERT_TRUE(simulated.start());
    connection::StationConnection station{support::withEmbeddedStation()};
    binding::RailwayBinding railways{station};
    BusMonitorPanel panel;
    panel.setBuses(&station.buses());
    station.connectTo(simulated.url());
    ASSERT_TRUE(test::waitForState(station, connection::StationConnection::State::Ready));
    ASSERT_NE(railways.railway(), nullptr);
    ASSERT_TRUE(panel.setCommandFilter(QStringLiteral("loco.speed")));
    ASSERT_TRUE(panel.setLocIdFilter(QStringLiteral("mm2 24"))); // V 100 2023, standing in the demo
    panel.setFilterText(QStringLiteral("speed=500"));
    railways.railway()->setSpeed(V100, 500);
    const QAbstractItemModel& shown = *panel.table()->model();
    ASSERT_TRUE(QTest::qWaitFor([&] { return shown.rowCount() >= 2; }, FramesMs));
    EXPECT_EQ(cell(shown, 0, BusMonitorModel::DirectionColumn), QStringLiteral("→ sent"));
    EXPECT_EQ(cell(shown, 1, BusMonitorModel::DirectionColumn), QStringLiteral("← received"));
    for (int row = 0; row < 2; ++row) {
        EXPECT_EQ(cell(shown, row, BusMonitorModel::MessageColumn), QStringLiteral("loco.speed"));
        EXPECT_TRUE(cell(shown, row, BusMonitorModel::DetailsColumn).contains(QStringLiteral("locId=0x0018")))
            << cell(shown, row, BusMonitorModel::DetailsColumn).toStdString();
    }
    const QColor sent =
        shown.index(0, BusMonitorModel::DirectionColumn).data(Qt::ForegroundRole).value<QColor>();
    const QColor received =
        shown.index(1, BusMonitorModel::DirectionColumn).data(Qt::ForegroundRole).value<QColor>();
    EXPECT_NE(sent, received);
}
