// The band of a block: drawn in from the sides where the block ends, so that two blocks side by side show
// where one ends; without the corner that would poke out where its track turns; its name on a tab where
// nothing else is drawn.
#include "trackplan/BlockOutlines.h"

#include "trackplan/TrackColors.h"

#include <QApplication>
#include <QImage>
#include <QPainter>
#include <QPalette>
#include <gtest/gtest.h>

using namespace stellwerk::ui;

namespace {

constexpr int Tile = 40;

BlockOutlines::Layout layoutOf(QRect room = QRect(0, 0, 20 * Tile, 10 * Tile)) {
    return {Tile, QPoint(0, 0), QApplication::font(), room, 1};
}

QImage painted(const BlockOutlines& outlines, const TrackColors& colors) {
    QImage image(20 * Tile, 10 * Tile, QImage::Format_ARGB32_Premultiplied);
    image.fill(colors.background);
    QPainter painter(&image);
    outlines.paintBands(painter, image.rect(), colors);
    outlines.paintNames(painter, image.rect());
    return image;
}

bool isBackground(const QImage& image, int x, int y, const TrackColors& colors) {
    return QColor(image.pixel(x, y)) == colors.background;
}

} // namespace

// An L: along row 2 from column 2 to 4, then down column 4 to row 4. The inner corner (bottom left of the
// cell at 4,2) stays empty like the other edges; the cells are filled up to the band's edge.
TEST(BlockOutlinesTest, ABandTurningACornerHasNoCornerPokingOut) {
    const TrackColors colors = TrackColors::from(QApplication::palette());
    BlockOutlines outlines({{1, QStringLiteral("L"), {{2, 2}, {3, 2}, {4, 2}, {4, 3}, {4, 4}}, {{3, 2}}}});
    outlines.layOut(layoutOf(), {}, colors);
    const QImage image = painted(outlines, colors);
    const int inset = Tile / 10;
    // The inner corner: just inside cell (4,2)'s bottom left, where neither the row's nor the column's band
    // reaches.
    EXPECT_TRUE(isBackground(image, 4 * Tile + 1, 3 * Tile - 2, colors)) << "no corner poking out";
    EXPECT_FALSE(isBackground(image, 4 * Tile + inset + 3, 3 * Tile - 2, colors)) << "the column's band";
    EXPECT_FALSE(isBackground(image, 4 * Tile - 3, 3 * Tile - inset - 3, colors)) << "the row's band";
    // Inside the band the cells join without a seam; outside its edge, nothing.
    EXPECT_EQ(QColor(image.pixel(3 * Tile, 2 * Tile + Tile / 2)),
              QColor(image.pixel(3 * Tile + 10, 2 * Tile + Tile / 2)));
    EXPECT_TRUE(isBackground(image, 2 * Tile + 1, 2 * Tile + Tile / 2, colors));
    EXPECT_EQ(QColor(image.pixel(2 * Tile + inset, 2 * Tile + Tile / 2)), colors.block) << "its edge";
}

// Two blocks that meet at a cell border each end short of it, so that the plan shows where one ends.
TEST(BlockOutlinesTest, TwoBlocksSideBySideShowWhereOneEnds) {
    const TrackColors colors = TrackColors::from(QApplication::palette());
    BlockOutlines outlines({{1, QStringLiteral("West"), {{1, 3}, {2, 3}}, {{1, 3}}},
                            {2, QStringLiteral("East"), {{3, 3}, {4, 3}}, {{3, 3}}}});
    outlines.layOut(layoutOf(), {}, colors);
    const QImage image = painted(outlines, colors);
    const int y = 3 * Tile + Tile / 2;
    EXPECT_TRUE(isBackground(image, 3 * Tile - 1, y, colors));
    EXPECT_TRUE(isBackground(image, 3 * Tile, y, colors));
    EXPECT_EQ(outlines.bandRect(1).right() + 1 + 2 * (Tile / 10), outlines.bandRect(2).left());
}

// The name goes below the middle of the block where that is free, above it where something is drawn
// below, and inside the band where both are taken; never outside the page.
TEST(BlockOutlinesTest, TheNameGoesWhereNothingElseIsDrawn) {
    const TrackColors colors = TrackColors::from(QApplication::palette());
    const BlockOutlines::Block block{
        1, QStringLiteral("Gleis 1"), {{2, 3}, {3, 3}, {4, 3}}, {{3, 3}, {2, 3}, {4, 3}}};
    BlockOutlines free({block});
    free.layOut(layoutOf(), {}, colors);
    EXPECT_EQ(free.nameRect(1).top(), 4 * Tile + 1) << "just below the band's row";
    EXPECT_EQ(free.nameRect(1).center().x(), QRect(3 * Tile, 3 * Tile, Tile, Tile).center().x());

    BlockOutlines below({block});
    below.layOut(layoutOf(), {QRect(0, 4 * Tile, 20 * Tile, Tile)}, colors);
    EXPECT_EQ(below.nameRect(1).bottom(), 3 * Tile - 2) << "just above the band's row";

    BlockOutlines both({block});
    both.layOut(layoutOf(), {QRect(0, 4 * Tile, 20 * Tile, Tile), QRect(0, 2 * Tile, 20 * Tile, Tile)},
                colors);
    EXPECT_TRUE(QRect(2 * Tile, 3 * Tile, 3 * Tile, Tile).contains(both.nameRect(1))) << "inside the band";

    BlockOutlines top({{1, QStringLiteral("Top"), {{2, 0}}, {{2, 0}}}});
    top.layOut(layoutOf(QRect(0, 0, 20 * Tile, Tile + 5)), {}, colors);
    EXPECT_GE(top.nameRect(1).top(), 0);
    const QImage image = painted(free, colors);
    int letters = 0; // inside the tab's round corners, what is not the tab's colour
    const QRect tab = free.nameRect(1).adjusted(3, 3, -3, -3);
    for (int y = tab.top(); y <= tab.bottom(); ++y)
        for (int x = tab.left(); x <= tab.right(); ++x)
            letters += QColor(image.pixel(x, y)) != colors.block;
    EXPECT_GT(letters, 10) << "the name is written on its tab";
}
