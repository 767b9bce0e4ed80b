// The bus monitor's filters by command, Loc-ID and text, alone and together, over many rows in slices,
// and the history bound.

#include "monitor/BusMonitorFilter.h"

#include "can/FrameText.h"
#include "monitor/BusMonitorModel.h"
#include "monitor/BusMonitorPanel.h"
#include "monitor/BusMonitorSettings.h"
#include "shell/Translations.h"
#include "support/MonitorTestSupport.h"

#include <QLabel>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTableView>
#include <QTest>
#include <gtest/gtest.h>
#include <vector>

using namespace stellwerk;
using namespace stellwerk::ui;
using Direction = BusMonitorModel::Direction;

using test::frame;

namespace {

// loco.speed DCC 3 speed 288, loco.speed MM2 24 speed 0, loco.direction DCC 3, system.stop.
std::vector<can::CanFrame> mixedFrames() {
    return {frame("00084711 6 00 00 C0 03 01 20"), frame("00084711 6 00 00 00 18 00 00"),
            frame("000A4711 5 00 00 C0 03 01"), frame("00004711 5 00 00 00 00 00")};
}

class BusMonitorFilterTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(translations.select(Language::English));
        panel.model()->addFrames(mixedFrames(), Direction::Received);
        panel.model()->flush();
    }
    int shown() const { return panel.table()->model()->rowCount(); }
    QString message(int row) const {
        return panel.table()->model()->index(row, BusMonitorModel::MessageColumn).data().toString();
    }

    Translations translations;
    BusMonitorPanel panel;
};

} // namespace

TEST(BusMonitorFilterLocId, ReadsHexDecimalAndProtocolAddress) {
    EXPECT_EQ(BusMonitorFilter::parseLocId(QStringLiteral("0xC003")), 0xC003u);
    EXPECT_EQ(BusMonitorFilter::parseLocId(QStringLiteral("49155")), 0xC003u);
    EXPECT_EQ(BusMonitorFilter::parseLocId(QStringLiteral(" DCC  3 ")), 0xC003u);
    EXPECT_EQ(BusMonitorFilter::parseLocId(QStringLiteral("mm2 24")), 0x18u);
    EXPECT_EQ(BusMonitorFilter::parseLocId(QStringLiteral("mfx 5")), 0x4005u);
    EXPECT_FALSE(BusMonitorFilter::parseLocId(QStringLiteral("steam 3")));
    EXPECT_FALSE(BusMonitorFilter::parseLocId(QStringLiteral("0xZZ")));
    EXPECT_FALSE(BusMonitorFilter::parseLocId(QStringLiteral("dcc")));
}

TEST_F(BusMonitorFilterTest, CommandAloneShowsOnlyThatCommand) {
    ASSERT_EQ(shown(), 4);
    ASSERT_TRUE(panel.setCommandFilter(QStringLiteral("loco.speed")));
    ASSERT_EQ(shown(), 2);
    EXPECT_EQ(message(0), QStringLiteral("loco.speed"));
    EXPECT_EQ(message(1), QStringLiteral("loco.speed"));
    EXPECT_FALSE(panel.setCommandFilter(QStringLiteral("loco.teleport")));
    EXPECT_EQ(shown(), 2);
    ASSERT_TRUE(panel.setCommandFilter(QString()));
    EXPECT_EQ(shown(), 4);
}

TEST_F(BusMonitorFilterTest, LocIdAloneShowsEveryCommandForThatLoco) {
    ASSERT_TRUE(panel.setLocIdFilter(QStringLiteral("dcc 3")));
    ASSERT_EQ(shown(), 2);
    EXPECT_EQ(message(0), QStringLiteral("loco.speed"));
    EXPECT_EQ(message(1), QStringLiteral("loco.direction"));
    ASSERT_TRUE(panel.setLocIdFilter(QStringLiteral("0x0018")));
    EXPECT_EQ(shown(), 1);
}

TEST_F(BusMonitorFilterTest, AllThreeTogetherNarrowStepByStep) {
    ASSERT_TRUE(panel.setCommandFilter(QStringLiteral("loco.speed")));
    ASSERT_TRUE(panel.setLocIdFilter(QStringLiteral("0xC003")));
    ASSERT_EQ(shown(), 1);
    EXPECT_EQ(message(0), QStringLiteral("loco.speed"));
    panel.setFilterText(QStringLiteral("SPEED=288"));
    EXPECT_EQ(shown(), 1);
    panel.setFilterText(QStringLiteral("speed=0"));
    EXPECT_EQ(shown(), 0) << "speed 0 is the MM2 loco's, which the Loc-ID excludes";
    ASSERT_TRUE(panel.setLocIdFilter(QString()));
    EXPECT_EQ(shown(), 1);
    auto* counter = panel.findChild<QLabel*>(QStringLiteral("busMonitorCounter"));
    ASSERT_NE(counter, nullptr);
    EXPECT_TRUE(counter->text().contains(QStringLiteral("1 row matches the filter")))
        << counter->text().toStdString();
}

TEST_F(BusMonitorFilterTest, ALocIdThatCannotBeReadIsReportedAndIgnored) {
    ASSERT_TRUE(panel.setCommandFilter(QStringLiteral("loco.direction")));
    EXPECT_FALSE(panel.setLocIdFilter(QStringLiteral("the red one")));
    EXPECT_EQ(shown(), 1);
    auto* counter = panel.findChild<QLabel*>(QStringLiteral("busMonitorCounter"));
    EXPECT_TRUE(counter->text().contains(QStringLiteral("Loc-ID is not understood")))
        << counter->text().toStdString();
}

TEST_F(BusMonitorFilterTest, NewFramesArePassedThroughTheFilter) {
    ASSERT_TRUE(panel.setLocIdFilter(QStringLiteral("dcc 3")));
    panel.model()->addFrames(mixedFrames(), Direction::Sent);
    panel.model()->flush();
    EXPECT_EQ(shown(), 4);
}

// The history set in the panel bounds the table: the oldest frames go, the newest stay, in order.
TEST(BusMonitorHistory, TheOldestFramesGoWhenTheHistoryIsFull) {
    BusMonitorPanel panel;
    auto* history = panel.findChild<QSpinBox*>(QStringLiteral("busMonitorHistory"));
    ASSERT_NE(history, nullptr);
    EXPECT_EQ(history->maximum(), 1000000);
    history->setValue(BusMonitorSettings::MinimumHistory);
    std::vector<can::CanFrame> frames;
    for (int i = 0; i < 2500; ++i) {
        can::CanFrame numbered = frame("00084711 6 00 00 C0 03 00 00");
        numbered.data[4] = std::uint8_t(i >> 8);
        numbered.data[5] = std::uint8_t(i);
        frames.push_back(numbered);
    }
    panel.model()->addFrames({frames.data(), 1200}, Direction::Received);
    panel.model()->flush();
    panel.model()->addFrames({frames.data() + 1200, 1300}, Direction::Received);
    panel.model()->flush();
    const BusMonitorModel& model = *panel.model();
    ASSERT_EQ(model.rowCount(), 1000);
    EXPECT_EQ(model.frameAt(0), frames[1500]);
    EXPECT_EQ(model.frameAt(999), frames[2499]);
    EXPECT_EQ(model.totalFrames(), 2500u);
}

TEST(BusMonitorHistory, AMillionFramesCanBeKept) {
    BusMonitorModel model;
    model.setHistoryLimit(BusMonitorSettings::MaximumHistory);
    EXPECT_EQ(model.historyLimit(), 1000000);
    const std::vector<can::CanFrame> batch(10001, frame("00004711 5 00 00 00 00 00"));
    for (int i = 0; i < 100; ++i) {
        model.addFrames(batch, Direction::Received);
        model.flush();
    }
    EXPECT_EQ(model.rowCount(), 1000000);
    EXPECT_EQ(model.totalFrames(), 1000100u);
}

namespace {

// Frame n of a numbered run: loco.speed for DCC 3 when n is even (speed n % 1000), system.stop when odd.
can::CanFrame numbered(int n) {
    if (n % 2 == 1)
        return frame("00004711 5 00 00 00 00 00");
    can::CanFrame speed = frame("00084711 6 00 00 C0 03 00 00");
    speed.data[4] = std::uint8_t((n % 1000) >> 8);
    speed.data[5] = std::uint8_t(n % 1000);
    return speed;
}

std::vector<can::CanFrame> numberedRun(int first, int count) {
    std::vector<can::CanFrame> frames;
    for (int n = first; n < first + count; ++n)
        frames.push_back(numbered(n));
    return frames;
}

// Every shown row is the source row it maps to, and they come in the source's order.
void expectConsistent(const BusMonitorFilter& filter, const BusMonitorModel& model) {
    int previous = -1;
    for (int row = 0; row < filter.rowCount(); ++row) {
        const QModelIndex source = filter.mapToSource(filter.index(row, 0));
        ASSERT_TRUE(source.isValid()) << row;
        EXPECT_GT(source.row(), previous);
        previous = source.row();
        EXPECT_EQ(filter.mapFromSource(source).row(), row);
        EXPECT_EQ(filter.index(row, BusMonitorModel::MessageColumn).data().toString(),
                  model.index(source.row(), BusMonitorModel::MessageColumn).data().toString());
    }
}

} // namespace

// A text filter over many rows is tested in slices between events; rows that come and go meanwhile are
// accounted for, and the result is the same as testing them all at once.
TEST(BusMonitorFilterScan, ManyRowsAreFilteredInSlicesWhileFramesComeAndGo) {
    BusMonitorModel model;
    model.setHistoryLimit(100000);
    BusMonitorFilter filter;
    filter.setSourceModel(&model);
    model.addFrames(numberedRun(0, 60000), Direction::Received);
    model.flush();
    QSignalSpy progress(&filter, &BusMonitorFilter::scanProgress);
    filter.setText(QStringLiteral("SPEED="));                        // every even frame
    model.addFrames(numberedRun(60000, 50000), Direction::Received); // 10,000 of the oldest go
    model.flush();
    ASSERT_TRUE(QTest::qWaitFor([&] { return !filter.isScanning(); }, 60000));
    EXPECT_EQ(model.rowCount(), 100000);
    EXPECT_EQ(filter.rowCount(), 50000);
    EXPECT_EQ(filter.scanPercent(), 100);
    ASSERT_FALSE(progress.isEmpty());
    EXPECT_EQ(progress.last().at(0).toInt(), 100);
    expectConsistent(filter, model);
    EXPECT_EQ(model.frameAt(filter.mapToSource(filter.index(0, 0)).row()), numbered(10000));
}

TEST(BusMonitorFilterScan, DroppingTheOldestRowsDropsTheirFilteredRows) {
    BusMonitorModel model;
    model.setHistoryLimit(1000);
    BusMonitorFilter filter;
    filter.setSourceModel(&model);
    filter.setCommand(QStringLiteral("loco.speed"));
    QSignalSpy removed(&filter, &QAbstractItemModel::rowsRemoved);
    for (int first = 0; first < 1500; first += 300) {
        model.addFrames(numberedRun(first, 300), Direction::Received);
        model.flush();
    }
    ASSERT_FALSE(filter.isScanning());
    EXPECT_EQ(model.rowCount(), 1000);
    EXPECT_EQ(filter.rowCount(), 500);
    EXPECT_GE(removed.count(), 1);
    expectConsistent(filter, model);
    EXPECT_EQ(model.frameAt(filter.mapToSource(filter.index(0, 0)).row()), numbered(500));
    EXPECT_EQ(model.frameAt(filter.mapToSource(filter.index(499, 0)).row()), numbered(1498));

    model.clear();
    EXPECT_EQ(filter.rowCount(), 0);
    model.addFrames(numberedRun(0, 4), Direction::Received);
    model.flush();
    EXPECT_EQ(filter.rowCount(), 2);
}
