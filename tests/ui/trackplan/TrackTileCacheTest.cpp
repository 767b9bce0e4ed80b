#include "trackplan/TrackTileCache.h"

#include "cs2config/TrackElementType.h"
#include "trackplan/TrackColors.h"
#include "trackplan/TrackTileLook.h"
#include "trackplan/TrackTilePainter.h"

#include <QApplication>
#include <QImage>
#include <QPainter>
#include <QPalette>
#include <gtest/gtest.h>
#include <string>
#include <vector>

using namespace stellwerk;
using namespace stellwerk::ui;

namespace {

constexpr int CachedTileSize = 40;
const QPoint Cell(3 * CachedTileSize, 2 * CachedTileSize);

TrackColors colors() {
    return TrackColors::from(QApplication::palette());
}

// A tile drawn into a blank picture of 6 x 4 cells, either straight from the painter or from the cache.
QImage drawn(const TrackTileLook& look, TrackTileCache* cache) {
    QImage image(6 * CachedTileSize, 4 * CachedTileSize, QImage::Format_ARGB32_Premultiplied);
    image.fill(colors().background);
    QPainter painter(&image);
    painter.setFont(QApplication::font());
    if (cache) {
        cache->prepare(CachedTileSize, 1.0, colors(), QApplication::font());
        cache->paint(painter, Cell, look);
    } else {
        TrackTilePainter::paint(painter, QRectF(Cell, QSizeF(CachedTileSize, CachedTileSize)), look,
                                colors());
    }
    return image;
}

// How many pixels differ by more than `tolerance` in a colour channel (anti-aliasing is not exactly
// the same for a picture drawn turned and one drawn upright and turned afterwards).
int differingTilePixels(const QImage& a, const QImage& b, int tolerance = 8) {
    int differing = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QColor p = a.pixelColor(x, y);
            const QColor q = b.pixelColor(x, y);
            differing += std::max({std::abs(p.red() - q.red()), std::abs(p.green() - q.green()),
                                   std::abs(p.blue() - q.blue())}) > tolerance;
        }
    return differing;
}

TrackTileLook look(const char* type, int rotation, int position = -1, QString text = {}) {
    const cs2config::TrackElementType* known = cs2config::findTrackElementType(type);
    const auto category = known ? known->category : cs2config::TrackCategory::Text;
    return {QString::fromLatin1(type), category, rotation, position, false, false, std::move(text)};
}

} // namespace

TEST(TrackTileCache, DrawsEveryTypeInEveryRotationAsThePainterDoes) {
    TrackTileCache cache;
    std::vector<TrackTileLook> tiles{look("text", 0, -1, QStringLiteral("Gleis 1")),
                                     look("text", 1, -1, QStringLiteral("Tunnel")),
                                     look("text", 2, -1, QStringLiteral("Bahnhof"))};
    for (const cs2config::TrackElementType& type : cs2config::trackElementTypes())
        for (int rotation = 0; rotation < 4; ++rotation)
            tiles.push_back(look(std::string(type.name).c_str(), rotation, type.switchable() ? 1 : -1));
    // A turned picture may differ from one drawn turned in the anti-aliasing of a few edge pixels; a
    // picture turned the wrong way differs in dozens.
    ASSERT_GT(differingTilePixels(drawn(look("linksweiche", 0, 0), nullptr),
                                  drawn(look("linksweiche", 1, 0), nullptr)),
              40);
    for (const TrackTileLook& tile : tiles) {
        const QImage direct = drawn(tile, nullptr);
        EXPECT_LE(differingTilePixels(drawn(tile, &cache), direct), 4)
            << tile.type.toStdString() << tile.rotation;
        EXPECT_LE(differingTilePixels(drawn(tile, &cache), direct), 4) << "drawn again from the cache";
    }
}

TEST(TrackTileCache, DrawsAPagesPicturesAheadOnSeveralThreadsAsPaintWouldHave) {
    std::vector<TrackTileLook> page;
    for (const cs2config::TrackElementType& type : cs2config::trackElementTypes())
        for (int rotation = 0; rotation < 4; ++rotation)
            for (int position = -1; position < (type.switchable() ? 2 : 0); ++position)
                page.push_back(look(std::string(type.name).c_str(), rotation, position));
    page.push_back(page.front()); // a look twice is drawn once
    const TrackTileLook label = look("text", 1, -1, QStringLiteral("Bahnhof"));
    page.push_back(label);

    TrackTileCache ahead;
    ahead.prepare(CachedTileSize, 1.0, colors(), QApplication::font());
    ahead.drawAhead(page);
    const int drawnAhead = ahead.size();
    EXPECT_GT(drawnAhead, 900);
    page.pop_back();
    // Empty tiles and texts without a text are drawn (as nothing, or a font's text) when painted.
    std::erase_if(page, [](const TrackTileLook& tile) {
        return !TrackTilePainter::draws(tile) || TrackTilePainter::usesFont(tile);
    });
    for (const TrackTileLook& tile : page)
        EXPECT_LE(differingTilePixels(drawn(tile, &ahead), drawn(tile, nullptr)), 4)
            << tile.type.toStdString() << tile.rotation << " " << tile.position;
    EXPECT_EQ(ahead.size(), drawnAhead) << "painting the page found every picture drawn";
    drawn(label, &ahead);
    EXPECT_EQ(ahead.size(), drawnAhead + 1) << "a label is drawn when it is painted, on the GUI thread";
}

TEST(TrackTileCache, KeepsTheDrawnPartOfOnePicturePerLookAndStartsAfreshWhenTheSizeChanges) {
    TrackTileCache cache;
    cache.prepare(CachedTileSize, 1.0, colors(), QApplication::font());
    const QRect straight = cache.area(look("gerade", 0), Cell);
    EXPECT_EQ(straight.left(), Cell.x()) << "a straight runs from edge to edge";
    EXPECT_GE(straight.right(), Cell.x() + CachedTileSize - 1);
    EXPECT_LT(straight.height(), CachedTileSize / 3) << "only the part of the tile that is drawn on is kept";
    cache.area(look("gerade", 0), Cell + QPoint(CachedTileSize, 0));
    EXPECT_EQ(cache.size(), 1) << "the same look elsewhere uses the same picture";
    cache.area(look("linksweiche", 3, 0), Cell);
    cache.area(look("linksweiche", 3, 1), Cell);
    EXPECT_EQ(cache.size(), 5) << "each position of a turnout has its picture, turned from the upright one";

    const QRect label = cache.area(look("text", 0, -1, QStringLiteral("Bahnhof Stellwerkhausen")), Cell);
    EXPECT_GT(label.right(), Cell.x() + 3 * CachedTileSize) << "a label runs beyond its tile";

    cache.prepare(2 * CachedTileSize, 1.0, colors(), QApplication::font());
    EXPECT_EQ(cache.size(), 0);
    EXPECT_GE(cache.area(look("gerade", 0), Cell).width(), 2 * CachedTileSize);
}
