// How panels arrange their parts for the width they get: widgets wrapping into as many columns as fit
// (WrappingGrid: throttles, gauges), two parts side by side or stacked (SideBySide: loco list and editor).

#include "common/SideBySide.h"
#include "common/WrappingGrid.h"

#include <QApplication>
#include <QBoxLayout>
#include <QSplitter>
#include <gtest/gtest.h>

using namespace stellwerk::ui;

namespace {

// A widget that asks for 100 x 60 pixels, like a small throttle.
class Card final : public QWidget {
public:
    using QWidget::QWidget;
    QSize sizeHint() const override { return {100, 60}; }
    QSize minimumSizeHint() const override { return {100, 60}; }
};

class WrappingGridTest : public ::testing::Test {
protected:
    void SetUp() override {
        for (int i = 0; i < 3; ++i) {
            cards[i] = new Card(&grid);
            grid.add(cards[i]);
        }
        grid.show();
    }
    void widthIs(int width) {
        grid.resize(width, 400);
        QApplication::processEvents();
    }

    WrappingGrid grid;
    Card* cards[3] = {};
};

} // namespace

TEST_F(WrappingGridTest, AsManyColumnsAsTheWidthHolds) {
    widthIs(250);
    EXPECT_EQ(grid.columns(), 2);
    EXPECT_EQ(cards[0]->y(), cards[1]->y()) << "1 and 2 side by side";
    EXPECT_GT(cards[2]->y(), cards[0]->y()) << "3 on the next row";
    EXPECT_EQ(cards[2]->x(), cards[0]->x()) << "under 1, as on a page";
    EXPECT_LE(cards[1]->geometry().right(), 250);
}

TEST_F(WrappingGridTest, ANarrowGridStacksAndAWideOneLinesUp) {
    widthIs(120);
    EXPECT_EQ(grid.columns(), 1);
    EXPECT_LT(cards[0]->y(), cards[1]->y());
    EXPECT_LT(cards[1]->y(), cards[2]->y());
    widthIs(600);
    EXPECT_GE(grid.columns(), 5) << "600 px hold five or six cards with the room between them";
    EXPECT_EQ(cards[0]->y(), cards[2]->y());
    EXPECT_EQ(cards[0]->height(), 60) << "the spare height stays below, the cards keep theirs";
    EXPECT_EQ(cards[2]->width(), 100) << "fewer cards than columns keep their width";
}

TEST_F(WrappingGridTest, ARemovedWidgetLeavesNoGap) {
    widthIs(250);
    grid.remove(cards[1]);
    QApplication::processEvents();
    EXPECT_EQ(cards[0]->y(), cards[2]->y()) << "3 moves up beside 1";
}

TEST(SideBySide, TwoPartsSideBySideWhenWideAndStackedWhenNarrow) {
    QWidget panel;
    auto* parts = new QSplitter(&panel);
    auto* layout = new QVBoxLayout(&panel);
    layout->addWidget(parts);
    auto* row = new QHBoxLayout;
    layout->addLayout(row);
    panel.resize(900, 400);
    panel.show(); // a hidden widget gets its resize events only when shown
    SideBySide::arrange(&panel, parts, 700);
    SideBySide::arrange(&panel, row, 700);
    EXPECT_EQ(parts->orientation(), Qt::Horizontal);
    EXPECT_EQ(row->direction(), QBoxLayout::LeftToRight);
    panel.resize(500, 400);
    EXPECT_EQ(parts->orientation(), Qt::Vertical);
    EXPECT_EQ(row->direction(), QBoxLayout::TopToBottom);
    panel.resize(700, 400);
    EXPECT_EQ(parts->orientation(), Qt::Horizontal) << "exactly the width is wide enough";
}
