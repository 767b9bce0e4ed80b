// MS1 handhelds (M-CAN) beside the CS2 in the bus monitor and the frame decoder: each bus learns, from
// its frames in the order they arrived, which handle is a handheld's loco or system status; the protocol
// filter offers M-CAN, and the handheld filter takes either node of a pair or the handheld's name.

#include "monitor/BusMonitorFilter.h"
#include "monitor/BusMonitorModel.h"
#include "monitor/BusMonitorPanel.h"
#include "monitor/FrameDecoderPanel.h"
#include "shell/Translations.h"
#include "support/MonitorTestSupport.h"

#include <QComboBox>
#include <QLabel>
#include <QTableView>
#include <QTreeWidget>
#include <gtest/gtest.h>
#include <vector>

using namespace stellwerk;
using namespace stellwerk::ui;
using Direction = BusMonitorModel::Direction;
using test::cell;
using test::frame;

namespace {

// From the chapter-11 trace of the M-CAN document: an MS1 (slave node 43) logs into an ECoS (master node
// 42), sends its name, learns its system-status and loco handles and the loco's name, and takes the loco.
const char* const Ms1Session[] = {
    "1C03B0FE 8 00 02 04 B3 00 02 AB 00", // #16 login grant: node 43, start handle 2
    "18000A2B 2 40 2B",                   // #17 SD-handle request
    "18000A2A 8 40 2B 00 00 00 08 00 01", // #18 SD handle 8
    "180020AB 8 02 00 00 00 4B 53 20 4D", // #24 its name: "KS M"
    "180020AB 7 02 00 00 04 53 31 00",    // #25 "S1"
    "180009AB 2 03 00",                   // #27 SY-handle request
    "180009AA 8 03 00 00 00 00 03 00 01", // #30 SY handle 3
    "18000D2B 2 01 01",                   // #31 status type query (reads as a function query alone)
    "180009AB 4 80 02 00 00",             // #45 loco list
    "180009AA 8 80 02 00 00 00 09 00 01", // #46 loco handle 9
    "180024AA 8 02 00 00 00 30 30 33 20", // #77 the loco's name: "003 "
    "180024AA 8 02 00 00 04 31 33 31 2D", // #79 "131-"
    "180024AA 8 02 00 00 08 30 00 00 00", // #81 "0"
    "1400242B 6 03 00 00 08 00 01",       // #92 the MS1 takes the loco
};
constexpr int StatusQueryRow = 7;
constexpr int TakeRow = 13;
constexpr int SessionRows = 14;

std::vector<can::CanFrame> session(int first = 0, int count = SessionRows) {
    std::vector<can::CanFrame> frames;
    for (int i = first; i < first + count; ++i)
        frames.push_back(frame(Ms1Session[i]));
    return frames;
}

bool namesTheLoco(const QString& details) {
    return details.contains(QStringLiteral("object=loco loco=\"003 131-0\""));
}

} // namespace

TEST(BusMonitorMcan, RowsAreDescribedWithWhatTheirBusRevealedInArrivalOrder) {
    BusMonitorModel model;
    model.addFrames(session(0, 9), Direction::Received);
    model.addFrames(session(9, SessionRows - 9), Direction::Received);
    model.flush();
    ASSERT_EQ(model.rowCount(), SessionRows);
    EXPECT_EQ(cell(model, StatusQueryRow, BusMonitorModel::MessageColumn),
              QStringLiteral("mcan.status-query"));
    EXPECT_EQ(cell(model, StatusQueryRow, 0, BusMonitorModel::ProtocolRole), QStringLiteral("mcan"));
    EXPECT_EQ(model.protocolAt(TakeRow), busreading::Protocol::Mcan);
    EXPECT_TRUE(namesTheLoco(cell(model, TakeRow, BusMonitorModel::DetailsColumn)))
        << cell(model, TakeRow, BusMonitorModel::DetailsColumn).toStdString();
    EXPECT_EQ(model.index(TakeRow, 0).data(BusMonitorModel::GroupRole).toInt(),
              int(BusMonitorModel::Group::Handheld));
    ASSERT_TRUE(model.handheldAt(TakeRow));
    EXPECT_EQ(model.handheldAt(TakeRow)->node, 43);
    EXPECT_EQ(model.handheldAt(TakeRow)->name, "KS MS1");
}

// The context learns as frames arrive, not as rows are inserted: frames held back by a pause, and frames
// the history drops before they are shown, still teach it.
TEST(BusMonitorMcan, FramesTeachWhileHeldBackOrDroppedBeforeShown) {
    BusMonitorModel model;
    model.setHistoryLimit(2);
    model.setPaused(true);
    model.addFrames(session(), Direction::Received);
    model.setPaused(false);
    ASSERT_EQ(model.rowCount(), 2);
    EXPECT_TRUE(namesTheLoco(cell(model, 1, BusMonitorModel::DetailsColumn)));
}

TEST(BusMonitorMcan, ClearingTheTableKeepsWhatTheBusRevealedAndALogStartsAfresh) {
    BusMonitorModel model;
    model.addFrames(session(0, TakeRow), Direction::Received);
    model.flush();
    model.clear();
    model.addFrames(session(TakeRow, 1), Direction::Received);
    model.flush();
    EXPECT_TRUE(namesTheLoco(cell(model, 0, BusMonitorModel::DetailsColumn))) << "the bus goes on";
    model.forgetBusContexts();
    EXPECT_FALSE(cell(model, 0, BusMonitorModel::DetailsColumn).contains(QStringLiteral("object=")));
}

namespace {

// The MS1 session above, a poll of a second handheld (node 45) and a CS2 frame, on the monitor's screen.
class BusMonitorMcanFilter : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(translations.select(Language::English));
        panel.model()->addFrames(session(), Direction::Received);
        const std::vector others{frame("0C0007AD 4 00 00 00 2C"), test::systemStop()};
        panel.model()->addFrames(others, Direction::Received);
        panel.model()->flush();
    }
    int shown() const { return panel.table()->model()->rowCount(); }
    QString counter() const { return panel.findChild<QLabel*>(QStringLiteral("busMonitorCounter"))->text(); }

    Translations translations;
    BusMonitorPanel panel;
};

} // namespace

TEST_F(BusMonitorMcanFilter, TheProtocolFilterOffersMcan) {
    auto* box = panel.findChild<QComboBox*>(QStringLiteral("busMonitorProtocol"));
    ASSERT_NE(box, nullptr);
    EXPECT_GE(box->findText(QStringLiteral("M-CAN")), 0);
    ASSERT_TRUE(panel.setProtocolFilter(QStringLiteral("mcan")));
    EXPECT_EQ(shown(), SessionRows + 1);
    ASSERT_TRUE(panel.setProtocolFilter(QStringLiteral("cs2")));
    EXPECT_EQ(shown(), 1);
}

TEST_F(BusMonitorMcanFilter, TheHandheldFilterTakesEitherNodeOfThePairOrTheName) {
    ASSERT_TRUE(panel.setHandheldFilter(QStringLiteral("43")));
    EXPECT_EQ(shown(), SessionRows) << "the master's answers (node 42) and the login grant belong to it too";
    ASSERT_TRUE(panel.setHandheldFilter(QStringLiteral("42")));
    EXPECT_EQ(shown(), SessionRows);
    ASSERT_TRUE(panel.setHandheldFilter(QStringLiteral("ks ms1")));
    EXPECT_EQ(shown(), SessionRows) << "also the rows before the name was sent";
    ASSERT_TRUE(panel.setHandheldFilter(QStringLiteral("45")));
    EXPECT_EQ(shown(), 1);
    EXPECT_TRUE(panel.setCommandFilter(QStringLiteral("mcan.throttle")));
    ASSERT_TRUE(panel.setHandheldFilter(QStringLiteral("43")));
    EXPECT_EQ(shown(), 1);
    EXPECT_TRUE(counter().contains(QStringLiteral("1 row matches the filter"))) << counter().toStdString();
}

TEST_F(BusMonitorMcanFilter, AHandheldThatCannotBeReadIsReportedAndIgnored) {
    EXPECT_FALSE(panel.setHandheldFilter(QStringLiteral("126")));
    EXPECT_EQ(shown(), SessionRows + 2);
    EXPECT_TRUE(counter().contains(QStringLiteral("the handheld is not understood")))
        << counter().toStdString();
    EXPECT_TRUE(panel.setHandheldFilter(QString()));
    EXPECT_FALSE(counter().contains(QStringLiteral("handheld")));
}

// The pasted lines are one bus, read in order.
TEST(FrameDecoderPanelMcan, PastedLinesAreReadAsOneBus) {
    Translations translations;
    ASSERT_TRUE(translations.select(Language::English));
    FrameDecoderPanel panel;
    QString input;
    for (const char* line : Ms1Session)
        input += QLatin1String(line) + QLatin1Char('\n');
    panel.setInput(input);
    auto* table = panel.findChild<QTreeWidget*>(QStringLiteral("frameResults"));
    ASSERT_EQ(table->topLevelItemCount(), SessionRows);
    EXPECT_EQ(table->topLevelItem(StatusQueryRow)->text(2), QStringLiteral("mcan.status-query"));
    EXPECT_TRUE(namesTheLoco(table->topLevelItem(TakeRow)->text(3)))
        << table->topLevelItem(TakeRow)->text(3).toStdString();
    panel.setInput(QLatin1String(Ms1Session[StatusQueryRow]));
    EXPECT_EQ(table->topLevelItem(0)->text(2), QStringLiteral("mcan.function-query"))
        << "alone, the handle is not known";
}
