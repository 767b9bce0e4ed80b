#include "trackplan/TrackTilePainter.h"

#include "cs2config/TrackElementType.h"
#include "trackplan/TrackColors.h"
#include "trackplan/TrackShapes.h"
#include "trackplan/TrackTileLook.h"

#include <QImage>
#include <QPainter>
#include <QPalette>
#include <gtest/gtest.h>
#include <set>

using namespace stellwerk;
using namespace stellwerk::ui;

namespace {

constexpr int PaintedTileSize = 48;

QPalette paletteOf(bool dark) {
    QPalette palette;
    palette.setColor(QPalette::Base, dark ? QColor(32, 32, 36) : QColor(255, 255, 255));
    palette.setColor(QPalette::Text, dark ? QColor(230, 230, 230) : QColor(20, 20, 20));
    palette.setColor(QPalette::Button, dark ? QColor(60, 60, 64) : QColor(230, 230, 230));
    palette.setColor(QPalette::Highlight, QColor(42, 130, 218));
    return palette;
}

QImage renderTile(const TrackTileLook& look, bool dark) {
    const TrackColors colors = TrackColors::from(paletteOf(dark));
    QImage image(PaintedTileSize, PaintedTileSize, QImage::Format_ARGB32);
    image.fill(colors.background);
    QPainter painter(&image);
    TrackTilePainter::paint(painter, QRectF(0, 0, PaintedTileSize, PaintedTileSize), look, colors);
    return image;
}

// Pixels that differ clearly (not just by anti-aliasing) between two images.
int differences(const QImage& a, const QImage& b) {
    int count = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QColor p = a.pixelColor(x, y);
            const QColor q = b.pixelColor(x, y);
            if (std::abs(p.red() - q.red()) + std::abs(p.green() - q.green()) +
                    std::abs(p.blue() - q.blue()) >
                60)
                ++count;
        }
    return count;
}

QImage blank(bool dark) {
    QImage image(PaintedTileSize, PaintedTileSize, QImage::Format_ARGB32);
    image.fill(TrackColors::from(paletteOf(dark)).background);
    return image;
}

TrackTileLook lookOf(const cs2config::TrackElementType& type, int rotation) {
    TrackTileLook look;
    look.type = QString::fromLatin1(type.name.data(), qsizetype(type.name.size()));
    look.category = type.category;
    look.rotation = rotation;
    look.position = type.switchable() ? 0 : -1;
    look.text = QStringLiteral("Ab");
    return look;
}

// Shapes that look the same after half a turn, as on the CS2 (a straight has no direction).
const std::set<std::string_view> halfTurnSymmetric{"gerade",        "doppelbogen", "s88doppelbogen",
                                                   "unterfuehrung", "tunnel",      "hosentraeger",
                                                   "dkweiche",      "dkweiche_2",  "kreuzung"};

} // namespace

class TrackTilePainterTest : public ::testing::TestWithParam<bool> {};

TEST_P(TrackTilePainterTest, EveryTypeDrawsSomethingInEveryRotation) {
    const bool dark = GetParam();
    for (const cs2config::TrackElementType& type : cs2config::trackElementTypes()) {
        if (type.name == "leer")
            continue;
        for (int rotation = 0; rotation < 4; ++rotation)
            EXPECT_GT(differences(renderTile(lookOf(type, rotation), dark), blank(dark)), 20)
                << type.name << " rotation " << rotation;
    }
}

TEST_P(TrackTilePainterTest, RotationsLookDifferent) {
    const bool dark = GetParam();
    for (const cs2config::TrackElementType& type : cs2config::trackElementTypes()) {
        if (type.name == "leer" || type.name == "kreuzung") // a plain crossing looks alike in every rotation
            continue;
        QImage images[4];
        for (int rotation = 0; rotation < 4; ++rotation)
            images[rotation] = renderTile(lookOf(type, rotation), dark);
        EXPECT_GT(differences(images[0], images[1]), 10) << type.name;
        EXPECT_GT(differences(images[1], images[2]), 10) << type.name;
        EXPECT_GT(differences(images[2], images[3]), 10) << type.name;
        if (!halfTurnSymmetric.contains(type.name)) {
            EXPECT_GT(differences(images[0], images[2]), 10) << type.name;
            EXPECT_GT(differences(images[1], images[3]), 10) << type.name;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(LightAndDark, TrackTilePainterTest, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "Dark" : "Light"; });

TEST(TrackTilePainter, ATurnoutShowsWhichWayItIsSet) {
    TrackTileLook look{
        QStringLiteral("linksweiche"), cs2config::TrackCategory::Turnout, 0, 0, false, false, {}};
    const QImage diverging = renderTile(look, false);
    look.position = 1;
    EXPECT_GT(differences(diverging, renderTile(look, false)), 20);
}

TEST(TrackTilePainter, AnOccupiedContactIsHighlighted) {
    TrackTileLook look{
        QStringLiteral("s88kontakt"), cs2config::TrackCategory::Feedback, 0, -1, false, false, {}};
    const QImage free = renderTile(look, false);
    look.occupied = true;
    const QImage occupied = renderTile(look, false);
    EXPECT_GT(differences(free, occupied), 30);
    const QColor red = TrackColors::from(paletteOf(false)).occupied;
    EXPECT_EQ(occupied.pixelColor(PaintedTileSize / 2, PaintedTileSize * 26 / 100).rgb(),
              red.rgb()); // inside the contact's marker
}

TEST(TrackTilePainter, ARunningRouteButtonIsHighlighted) {
    TrackTileLook look{
        QStringLiteral("fahrstrasse"), cs2config::TrackCategory::RouteButton, 0, -1, false, false, {}};
    const QImage idle = renderTile(look, false);
    look.running = true;
    EXPECT_GT(differences(idle, renderTile(look, false)), 100);
}

TEST(TrackTilePainter, ASignalLightsTheLampOfItsAspect) {
    TrackTileLook look{QStringLiteral("signal"), cs2config::TrackCategory::Signal, 0, 0, false, false, {}};
    const QImage stop = renderTile(look, false);
    look.position = 1;
    const QImage proceed = renderTile(look, false);
    const TrackColors colors = TrackColors::from(paletteOf(false));
    const QPoint red = (shapes::lampCentre(0, 2) * PaintedTileSize).toPoint();
    const QPoint green = (shapes::lampCentre(1, 2) * PaintedTileSize).toPoint();
    EXPECT_EQ(stop.pixelColor(red).rgb(), colors.red.rgb());
    EXPECT_EQ(proceed.pixelColor(green).rgb(), colors.green.rgb());
    EXPECT_EQ(proceed.pixelColor(red).rgb(), colors.dim.rgb());
    // Readable at a glance: the lit lamp covers at least 3 % of the tile.
    int lit = 0;
    for (int y = 0; y < proceed.height(); ++y)
        for (int x = 0; x < proceed.width(); ++x)
            lit += proceed.pixelColor(x, y).rgb() == colors.green.rgb();
    EXPECT_GE(lit * 100, 3 * PaintedTileSize * PaintedTileSize) << lit << " green pixels";
}

namespace {

int tilePixelsOf(const QImage& image, const QColor& color) {
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            count += image.pixelColor(x, y).rgb() == color.rgb();
    return count;
}

} // namespace

// A semaphore reads as well as a light signal: its arm in the aspect's colour covers at least as much of the
// tile as a lit lamp, and it is raised (reaching higher up the tile) at proceed.
TEST(TrackTilePainter, AFormSignalShowsItsArmLargeInTheColourOfItsAspect) {
    TrackTileLook look{
        QStringLiteral("signal_f_hp01"), cs2config::TrackCategory::Signal, 0, 0, false, false, {}};
    const TrackColors colors = TrackColors::from(paletteOf(false));
    const QImage stop = renderTile(look, false);
    look.position = 1;
    const QImage proceed = renderTile(look, false);
    // (The arm of 20 px by 4 px drawn before covered 2.5 % at stop, 1.6 % raised.)
    EXPECT_GE(tilePixelsOf(stop, colors.red) * 1000, 45 * PaintedTileSize * PaintedTileSize)
        << "a red arm at stop";
    EXPECT_GE(tilePixelsOf(proceed, colors.green) * 100, 3 * PaintedTileSize * PaintedTileSize)
        << "a green arm at proceed, partly behind the track";
    EXPECT_EQ(tilePixelsOf(proceed, colors.red), 0);
    const auto middle = [](const QImage& image, const QColor& color) { // the mean row of the colour
        double rows = 0;
        int count = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                if (image.pixelColor(x, y).rgb() == color.rgb()) {
                    rows += y;
                    ++count;
                }
        return count ? rows / count : 0.0;
    };
    EXPECT_LT(middle(proceed, colors.green) + PaintedTileSize / 10.0, middle(stop, colors.red))
        << "raised at proceed";
}

TEST(TrackTilePainter, AnUnknownTypeStillShowsAMark) {
    const TrackTileLook look{
        QStringLiteral("custom_perm_left"), cs2config::TrackCategory::Unknown, 0, -1, false, false, {}};
    EXPECT_GT(differences(renderTile(look, false), blank(false)), 20);
}
