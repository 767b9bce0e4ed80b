// The plan's zoom, page by page: a page first shows its drawn part filling the window and keeps doing so
// while the window changes size, until the user zooms; each page keeps its own zoom.

#include "trackplan/PageZoom.h"

#include "trackplan/TrackPageView.h"
#include "trackplan/TrackPlanPanel.h"
#include "trackplan/TrackTileLook.h"
#include "trackplan/TrackTilePainter.h"

#include <QScrollArea>
#include <QTabWidget>
#include <QTest>
#include <filesystem>
#include <gtest/gtest.h>

using namespace stellwerk::ui;

namespace {

// A real station's plan (can2udp's example files): two pages, drawn in a corner of a large grid.
QString corpusLayout() {
    return QString::fromStdString(
        (std::filesystem::path(STELLWERK_SHARED_DIR) / "corpus/GBert__railroad/can2udp/files/maerklin")
            .string());
}

// The demo layout's folder: three pages.
QString demoLayout() {
    return QStringLiteral(STELLWERK_SOURCE_DIR "/resources/demo-layout");
}

class PageZoomTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(panel.openFolder(corpusLayout()));
        panel.resize(900, 500);
        panel.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&panel));
        QTest::qWait(50);
    }
    QScrollArea* scroll(int page) const { return qobject_cast<QScrollArea*>(panel.pageTabs()->widget(page)); }
    // The drawn part of the page in pixels of its view.
    QRect drawnPixels(int page) const {
        const TrackPageView* view = panel.pageView(page);
        const QRect cells = view->drawnCells();
        const int tile = view->tileSize();
        return {TrackPageView::Margin + cells.left() * tile, TrackPageView::Margin + cells.top() * tile,
                cells.width() * tile, cells.height() * tile};
    }
    // The part of the page's view its window shows, in the view's pixels.
    QRect shownPixels(int page) const {
        const QScrollArea* area = scroll(page);
        return QRect(panel.pageView(page)->mapFrom(area->viewport(), QPoint(0, 0)), area->viewport()->size());
    }

    TrackPlanPanel panel;
};

} // namespace

TEST_F(PageZoomTest, APageFirstShowsItsDrawnPartFillingTheWindow) {
    ASSERT_GE(panel.pageTabs()->count(), 1);
    const TrackPageView* view = panel.pageView(0);
    ASSERT_FALSE(view->drawnCells().isEmpty());
    EXPECT_LT(view->drawnCells().width() * view->drawnCells().height(),
              view->gridSize().width() * view->gridSize().height())
        << "the example is drawn in a part of its grid";
    EXPECT_TRUE(panel.isFitted());
    const QRect drawn = drawnPixels(0);
    const QRect shown = shownPixels(0);
    EXPECT_TRUE(shown.contains(drawn)) << "all of the drawn part is in sight";
    const bool fillsWidth = drawn.width() * 10 >= shown.width() * 8;
    const bool fillsHeight = drawn.height() * 10 >= shown.height() * 8;
    EXPECT_TRUE(fillsWidth || fillsHeight)
        << "it fills the window in one direction: " << drawn.width() << "x" << drawn.height() << " in "
        << shown.width() << "x" << shown.height();
}

TEST_F(PageZoomTest, AFittedPageFollowsTheWindowUntilTheUserZooms) {
    const int small = panel.tileSize();
    panel.resize(1400, 900);
    QTest::qWait(50);
    const int large = panel.tileSize();
    EXPECT_GT(large, small) << "a larger window shows the plan larger";
    EXPECT_TRUE(shownPixels(0).contains(drawnPixels(0)));

    panel.zoomOut();
    const int chosen = panel.tileSize();
    EXPECT_LT(chosen, large);
    EXPECT_FALSE(panel.isFitted());
    panel.resize(900, 500);
    QTest::qWait(50);
    EXPECT_EQ(panel.tileSize(), chosen) << "the user's zoom stays when the window changes";

    panel.fitToWindow();
    EXPECT_TRUE(panel.isFitted());
    EXPECT_EQ(panel.tileSize(), small) << "Fit goes back to the drawn part in this window";
}

TEST_F(PageZoomTest, EachPageKeepsItsOwnZoom) {
    ASSERT_TRUE(panel.openFolder(demoLayout()));
    ASSERT_EQ(panel.pageTabs()->count(), 3);
    panel.pageTabs()->setCurrentIndex(1);
    QTest::qWait(20);
    const int second = panel.tileSize();
    panel.pageTabs()->setCurrentIndex(0);
    panel.setTileSize(PageZoom::MinimumTile);
    EXPECT_EQ(panel.tileSize(), PageZoom::MinimumTile);
    panel.pageTabs()->setCurrentIndex(1);
    EXPECT_EQ(panel.tileSize(), second) << "zooming page 1 left page 2 as it was";
    EXPECT_TRUE(panel.isFitted());
    panel.pageTabs()->setCurrentIndex(0);
    EXPECT_EQ(panel.tileSize(), PageZoom::MinimumTile);
}

TEST_F(PageZoomTest, TheZoomStaysWhenTheLayoutIsOpenedAgain) {
    panel.setTileSize(30);
    ASSERT_TRUE(panel.openFolder(corpusLayout()));
    QTest::qWait(20);
    EXPECT_EQ(panel.tileSize(), 30);
    EXPECT_FALSE(panel.isFitted());
}

// The demo's Bw page ends its three tracks with "Lokschuppen 1/2/3", written beyond the last tile: a
// fitted page shows all of every such text, and the page scrolls far enough to reach it at any zoom.
TEST_F(PageZoomTest, AFittedPageShowsTheTextsThatRunBeyondTheirTiles) {
    ASSERT_TRUE(panel.openFolder(demoLayout()));
    for (const QSize size : {QSize(560, 380), QSize(900, 500), QSize(1300, 700)}) {
        panel.resize(size);
        for (int page = 0; page < panel.pageTabs()->count(); ++page) {
            panel.pageTabs()->setCurrentIndex(page);
            panel.fitToWindow();
            QTest::qWait(20);
            const TrackPageView* view = panel.pageView(page);
            const QRect shown = shownPixels(page);
            const auto& tiles = panel.layout()->pages().at(std::size_t(page)).tiles;
            int texts = 0;
            for (int tile = 0; tile < int(tiles.size()); ++tile) {
                if (tiles.at(std::size_t(tile)).category != stellwerk::cs2config::TrackCategory::Text)
                    continue;
                ++texts;
                const QRect text =
                    TrackTilePainter::area(view->tileRect(tile), panel.lookOf({page, tile}), view->font())
                        .toAlignedRect();
                EXPECT_TRUE(shown.contains(text))
                    << "\"" << tiles.at(std::size_t(tile)).text.toStdString() << "\" on page " << page
                    << " at " << size.width() << "x" << size.height() << " is cut: " << text.left() << ".."
                    << text.right() << " shown " << shown.left() << ".." << shown.right();
                EXPECT_LE(text.right() + 1, view->width()) << "the page reaches the end of the text";
            }
            EXPECT_GT(texts, 0);
        }
    }
}
