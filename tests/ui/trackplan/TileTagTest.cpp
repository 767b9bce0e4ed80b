// The names elements carry in their files (turnout numbers, signal names, S88 numbers, route names) are
// drawn on the plan where they are readable.

#include "trackplan/TileTag.h"

#include "model/TrackLayout.h"
#include "trackplan/NameElision.h"
#include "trackplan/TrackColors.h"
#include "trackplan/TrackPageView.h"
#include "trackplan/TrackPlanPanel.h"

#include <QApplication>
#include <QFontMetrics>
#include <QImage>
#include <QPainter>
#include <QTest>
#include <filesystem>
#include <gtest/gtest.h>

using namespace stellwerk;
using namespace stellwerk::ui;
using Category = cs2config::TrackCategory;

namespace {

model::LayoutTile tile(Category category, const QString& text) {
    model::LayoutTile tile;
    tile.category = category;
    tile.text = text;
    return tile;
}

const QRect Cell(100, 200, 40, 40);

} // namespace

TEST(TileTag, ContactsTurnoutsAndSignalsCarryTheirNameAtTheTopLeft) {
    for (const Category category : {Category::Feedback, Category::Turnout, Category::Signal}) {
        const TileTag tag(tile(category, QStringLiteral("603")), Cell, QApplication::font());
        ASSERT_TRUE(tag.shown());
        EXPECT_EQ(tag.text(), QStringLiteral("603"));
        EXPECT_EQ(tag.rect().topLeft(), Cell.topLeft() + QPoint(1, 1));
        EXPECT_TRUE(Cell.contains(tag.rect())) << "it stays on its tile";
    }
    const TileTag longName(tile(Category::Feedback, QStringLiteral("Einfahrt West")), Cell,
                           QApplication::font());
    EXPECT_TRUE(Cell.contains(longName.rect())) << "a long name is shortened to its tile";
}

TEST(TileTag, PlainTrackTextsAndEmptyNamesCarryNone) {
    EXPECT_FALSE(TileTag(tile(Category::Track, QStringLiteral("7")), Cell, QApplication::font()).shown());
    EXPECT_FALSE(TileTag(tile(Category::Text, QStringLiteral("Gleis 1")), Cell, QApplication::font()).shown())
        << "a text tile draws itself";
    EXPECT_FALSE(TileTag(tile(Category::Turnout, QStringLiteral("  ")), Cell, QApplication::font()).shown());
}

TEST(TileTag, TooSmallAZoomDrawsNoTag) {
    const QRect small(0, 0, TileTag::MinimumTile - 1, TileTag::MinimumTile - 1);
    EXPECT_FALSE(TileTag(tile(Category::Signal, QStringLiteral("D")), small, QApplication::font()).shown());
}

TEST(TileTag, ARouteNameStaysUnderItsButton) {
    const TileTag tag(tile(Category::RouteButton, QStringLiteral("Einfahrt von Westen über Gleis 2")), Cell,
                      QApplication::font());
    ASSERT_TRUE(tag.shown());
    EXPECT_TRUE(tag.text().contains(QStringLiteral("…"))) << "a long name is shortened to the tile";
    EXPECT_TRUE(tag.text().endsWith(QStringLiteral("s 2"))) << "keeping what tells it from its siblings";
    EXPECT_LE(tag.rect().width(), Cell.width() + 2);
    EXPECT_EQ(tag.rect().bottom(), Cell.bottom());
    EXPECT_NEAR(tag.rect().center().x(), Cell.center().x(), 1);
}

// Siblings on a plan differ at their end: shortened to a tile, "Block 1" … "Block 4" must not all read
// "Blo…", nor the two entry routes "Ein…".
TEST(TileTag, ShortenedSiblingNamesStayDistinct) {
    const QList<QStringList> families = {
        {QStringLiteral("Block 1"), QStringLiteral("Block 2"), QStringLiteral("Block 3"),
         QStringLiteral("Block 4")},
        {QStringLiteral("Einfahrt 1"), QStringLiteral("Einfahrt 2")},
        {QStringLiteral("Einfahrt Gleis 1"), QStringLiteral("Einfahrt Gleis 2")},
        {QStringLiteral("Lokschuppen1"), QStringLiteral("Lokschuppen2")}};
    for (const int tileSize : {TileTag::MinimumTile, 30, 40}) {
        const QRect cell(0, 0, tileSize, tileSize);
        const QFont font = TileTag::tagFont(QApplication::font(), tileSize);
        for (const Category category : {Category::Feedback, Category::RouteButton}) {
            for (const QStringList& family : families) {
                QStringList shown;
                for (const QString& name : family) {
                    const TileTag tag(tile(category, name), cell, font);
                    ASSERT_TRUE(tag.shown());
                    EXPECT_LE(tag.rect().width(), tileSize) << name.toStdString() << " stays on its tile";
                    EXPECT_TRUE(tag.text().endsWith(name.right(1)))
                        << tag.text().toStdString() << " lost the end of " << name.toStdString();
                    shown << tag.text();
                }
                shown.removeDuplicates();
                EXPECT_EQ(shown.size(), family.size())
                    << "at " << tileSize << " px: " << shown.join(QStringLiteral(", ")).toStdString();
            }
        }
    }
}

TEST(NameElision, KeepsTheLastWordWithTheCharacterBeforeIt) {
    const QFontMetrics metrics(QApplication::font());
    const QString name = QStringLiteral("Einfahrt Gleis 1");
    EXPECT_EQ(NameElision::shorten(name, metrics, 1000), name) << "a name that fits stays whole";
    const int room = metrics.horizontalAdvance(QStringLiteral("Einf…s 1"));
    const QString shortened = NameElision::shorten(name, metrics, room);
    EXPECT_EQ(shortened, QStringLiteral("Einf…s 1"));
    EXPECT_EQ(NameElision::shorten(name, metrics, metrics.horizontalAdvance(QStringLiteral("…s 1"))),
              QStringLiteral("…s 1"));
    const QString tiny = NameElision::shorten(name, metrics, metrics.horizontalAdvance(QStringLiteral("…1")));
    EXPECT_EQ(tiny, QStringLiteral("…1")) << "too narrow for the word: as much of the end as fits";
    EXPECT_EQ(NameElision::shorten(QStringLiteral("Bahnbetriebswerk"), metrics,
                                   metrics.horizontalAdvance(QStringLiteral("Bahn…"))),
              QStringLiteral("Bahn…"))
        << "a single word without a number ends where the room ends";
    const int narrow = metrics.horizontalAdvance(QStringLiteral("W…t"));
    const QString west = NameElision::shorten(QStringLiteral("Einfahrt West"), metrics, narrow);
    const QString east = NameElision::shorten(QStringLiteral("Ausfahrt Ost"), metrics, narrow);
    EXPECT_NE(west, east) << "names that end alike keep their start too: " << west.toStdString();
    EXPECT_TRUE(west.startsWith(QLatin1Char('E'))) << west.toStdString();
    EXPECT_TRUE(east.startsWith(QLatin1Char('A'))) << east.toStdString();
    EXPECT_EQ(NameElision::shorten(QStringLiteral("Block 12"), metrics,
                                   metrics.horizontalAdvance(QStringLiteral("…12"))),
              QStringLiteral("…12"))
        << "a number keeps its end";
}

TEST(TileTag, TagsAreDrawnInAReadableSize) {
    for (const int tileSize : {TileTag::MinimumTile, 30, 40, 160})
        EXPECT_GE(TileTag::tagFont(QApplication::font(), tileSize).pixelSize(), TileTag::ReadablePixels)
            << tileSize << " px tiles";
}

TEST(TileTag, TheCorpusPlanShowsItsContactAndTurnoutNumbers) {
    TrackPlanPanel panel;
    ASSERT_TRUE(panel.openFolder(QString::fromStdString(
        (std::filesystem::path(STELLWERK_SHARED_DIR) / "corpus/GBert__railroad/can2udp/files/maerklin")
            .string())));
    panel.resize(1200, 500);
    panel.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&panel));
    TrackPageView* view = panel.pageView(0);
    ASSERT_GE(view->tileSize(), TileTag::MinimumTile) << "fitted, the example is large enough for its names";
    const QImage image = view->grab().toImage();
    int tagged = 0;
    for (int i = 0; i < int(panel.layout()->pages()[0].tiles.size()); ++i) {
        const TileTag tag = view->tagOf(i);
        if (!tag.shown())
            continue;
        ++tagged;
        int dark = 0; // the text's pixels on the light backing
        for (int y = tag.rect().top(); y <= tag.rect().bottom(); ++y)
            for (int x = tag.rect().left(); x <= tag.rect().right(); ++x)
                dark += QColor(image.pixel(QPoint(x, y) * image.devicePixelRatio())).lightness() < 110;
        EXPECT_GT(dark, 4) << "tag \"" << tag.text().toStdString() << "\" is drawn";
    }
    EXPECT_GE(tagged, 10) << "the example names most of its turnouts, signals and contacts";
}

namespace {

// The dark pixels of a tag drawn on a white picture of its cell.
int darkPixelsOf(const TileTag& tag) {
    QImage image(Cell.right() + 10, Cell.bottom() + 10, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setFont(tag.font());
    tag.paint(painter, TrackColors::from(QApplication::palette()));
    painter.end();
    int dark = 0;
    for (int y = tag.rect().top(); y <= tag.rect().bottom(); ++y)
        for (int x = tag.rect().left(); x <= tag.rect().right(); ++x)
            dark += QColor(image.pixel(x, y)).lightness() < 110;
    return dark;
}

} // namespace

TEST(TileTag, ANameIsDrawnAsWideAsItsTextAndOneTheFontLacksStillShows) {
    const QFont font = TileTag::tagFont(QApplication::font(), Cell.width());
    const TileTag plain(tile(Category::Turnout, QStringLiteral("W12")), Cell, font);
    ASSERT_TRUE(plain.shown());
    EXPECT_NEAR(plain.rect().width(), QFontMetrics(font).horizontalAdvance(QStringLiteral("W12")) + 4, 1);
    EXPECT_GT(darkPixelsOf(plain), 8);
    EXPECT_LT(darkPixelsOf(TileTag(tile(Category::Turnout, QStringLiteral("W")), Cell, font)),
              darkPixelsOf(plain))
        << "its own glyphs are drawn, not a stand-in";

    // A character outside the font's tables (a locomotive, U+1F682, two UTF-16 units): Qt's own layout
    // draws it, from another font or as a box.
    const TileTag foreign(tile(Category::Signal, QString::fromUtf8("\xF0\x9F\x9A\x82"
                                                                   "1")),
                          Cell, font);
    ASSERT_TRUE(foreign.shown());
    EXPECT_GT(foreign.rect().width(), 4);
    EXPECT_GT(darkPixelsOf(foreign), 4);
}

TEST(TileTag, ABatchDrawsTheNamesAsEveryTagDrawnOnItsOwn) {
    const QFont font = TileTag::tagFont(QApplication::font(), Cell.width());
    std::vector<TileTag> tags;
    for (const QString& name : {QStringLiteral("W12"), QString::fromUtf8("\xF0\x9F\x9A\x82 3"),
                                QStringLiteral("Einfahrt West"), QStringLiteral("S")})
        tags.emplace_back(tile(Category::Signal, name), Cell.translated(int(tags.size()) * Cell.width(), 0),
                          font);
    const TrackColors colors = TrackColors::from(QApplication::palette());
    const auto picture = [&](const auto& paint) {
        QImage image(Cell.right() + 5 * Cell.width(), Cell.bottom() + 10,
                     QImage::Format_ARGB32_Premultiplied);
        image.fill(colors.track);
        QPainter painter(&image);
        painter.setFont(font);
        paint(painter);
        return image;
    };
    const QImage alone = picture([&](QPainter& painter) {
        for (const TileTag& tag : tags)
            tag.paint(painter, colors);
    });
    const QImage batched = picture([&](QPainter& painter) {
        TileTagBatch batch(font);
        for (const TileTag& tag : tags)
            batch.add(tag);
        batch.paintBackings(painter, colors, QRect(QPoint(0, 0), QSize(10000, 10000)));
        batch.paintGlyphs(painter, colors);
        batch.paintShaped(painter, colors);
    });
    EXPECT_TRUE(alone == batched);
    EXPECT_GT(darkPixelsOf(tags[0]), 8);
}
