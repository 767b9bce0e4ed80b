// The bus monitor's filters by command, Loc-ID and text, alone and together, and the history bound.

#include "BusMonitorFilter.h"

#include "BusMonitorModel.h"
#include "BusMonitorPanel.h"
#include "BusMonitorSettings.h"
#include "Translations.h"
#include "cs2/FrameText.h"

#include <QLabel>
#include <QSpinBox>
#include <QTableView>
#include <gtest/gtest.h>
#include <vector>

using namespace stellwerk;
using namespace stellwerk::ui;
using Direction = BusMonitorModel::Direction;

namespace {

cs2::CanFrame frame(const char* text) {
    return cs2::parseFrame(text).value().frame;
}

// loco.speed DCC 3 speed 288, loco.speed MM2 24 speed 0, loco.direction DCC 3, system.stop.
std::vector<cs2::CanFrame> mixedFrames() {
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
    std::vector<cs2::CanFrame> frames;
    for (int i = 0; i < 2500; ++i) {
        cs2::CanFrame numbered = frame("00084711 6 00 00 C0 03 00 00");
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
    const std::vector<cs2::CanFrame> batch(10001, frame("00004711 5 00 00 00 00 00"));
    for (int i = 0; i < 100; ++i) {
        model.addFrames(batch, Direction::Received);
        model.flush();
    }
    EXPECT_EQ(model.rowCount(), 1000000);
    EXPECT_EQ(model.totalFrames(), 1000100u);
}
