// The track graph's table of tile track (core/trackgraph TileShape) against the plan's drawings: for every
// tile type and rotation, the track leaves the drawn tile exactly at the sides and corners where the graph
// joins it to its neighbours, and a turnout drawn in each position shows in full exactly the legs the graph
// takes that position to set. This keeps the two in agreement when either changes.
#include "cs2config/TrackElementType.h"
#include "trackgraph/TileShape.h"
#include "trackplan/TrackColors.h"
#include "trackplan/TrackTileLook.h"
#include "trackplan/TrackTilePainter.h"

#include <QImage>
#include <QPainter>
#include <gtest/gtest.h>
#include <set>
#include <string>

using namespace stellwerk;
using namespace stellwerk::ui;
using trackgraph::Port;

namespace {

constexpr int Size = 64;

// Every colour its own, so that a pixel says what was drawn there: track is pure red, the legs a turnout
// is not set to pure blue.
TrackColors distinctColors() {
    TrackColors colors;
    colors.background = QColor(255, 255, 255);
    colors.grid = QColor(250, 250, 250);
    colors.track = QColor(255, 0, 0);
    colors.dim = QColor(0, 0, 255);
    colors.occupied = QColor(255, 128, 0);
    colors.red = QColor(128, 0, 0);
    colors.green = QColor(0, 128, 0);
    colors.yellow = QColor(200, 200, 0);
    colors.white = QColor(240, 240, 240);
    colors.button = QColor(200, 200, 200);
    colors.highlight = QColor(0, 200, 200);
    colors.text = QColor(0, 255, 0);
    return colors;
}

QImage render(const std::string& type, int rotation, int position) {
    QImage image(Size, Size, QImage::Format_ARGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    TrackTileLook look;
    look.type = QString::fromStdString(type);
    look.rotation = rotation;
    look.position = position;
    TrackTilePainter::paint(painter, QRectF(0, 0, Size, Size), look, distinctColors());
    return image;
}

// The pixel at the border where track leaves through a port: the middle of a side or a corner.
QPoint borderPixel(Port port) {
    const auto [dx, dy] = trackgraph::offsetOf(port);
    const auto at = [](int step) { return step < 0 ? 0 : step > 0 ? Size - 1 : Size / 2; };
    return {at(dx), at(dy)};
}

bool isTrack(const QColor& color) {
    return color.red() > 200 && color.green() < 90 && color.blue() < 90;
}

std::set<Port> drawnExits(const QImage& image) {
    std::set<Port> exits;
    for (int port = 0; port < trackgraph::GeometricPorts; ++port)
        if (isTrack(image.pixelColor(borderPixel(Port(port)))))
            exits.insert(Port(port));
    return exits;
}

std::set<Port> graphExits(const std::string& type, int rotation, std::optional<int> setIn = std::nullopt) {
    std::set<Port> exits;
    const trackgraph::TileShape shape = trackgraph::rotatedShape(trackgraph::tileShapeOf(type), rotation);
    for (const trackgraph::Leg& leg : shape.legs())
        if (!setIn || leg.setIn(*setIn))
            for (const Port port : {leg.from, leg.to})
                if (trackgraph::isGeometric(port))
                    exits.insert(port);
    return exits;
}

std::string names(const std::set<Port>& ports) {
    std::string text;
    for (const Port port : ports)
        text += std::string(trackgraph::portName(port)) + " ";
    return text;
}

} // namespace

TEST(TrackGraphDrawing, TrackLeavesEveryTileWhereTheGraphJoinsIt) {
    int checked = 0;
    for (const cs2config::TrackElementType& type : cs2config::trackElementTypes()) {
        const std::string name(type.name);
        for (int rotation = 0; rotation < 4; ++rotation) {
            const std::set<Port> drawn = drawnExits(render(name, rotation, -1));
            const std::set<Port> joined = graphExits(name, rotation);
            EXPECT_EQ(names(drawn), names(joined)) << name << " rotation " << rotation;
            checked += joined.empty() ? 0 : 1;
        }
    }
    EXPECT_GT(checked, 4 * 60); // every track type of the table was looked at, not only the empty ones
}

TEST(TrackGraphDrawing, ATurnoutDrawnInAPositionShowsTheLegsThatPositionSets) {
    for (const cs2config::TrackElementType& type : cs2config::trackElementTypes()) {
        const std::string name(type.name);
        const trackgraph::TileShape& shape = trackgraph::tileShapeOf(name);
        if (shape.role != trackgraph::TileRole::Turnout)
            continue;
        for (int position = 0; position < trackgraph::positionCount(shape.turnout); ++position)
            for (int rotation = 0; rotation < 4; ++rotation)
                EXPECT_EQ(names(drawnExits(render(name, rotation, position))),
                          names(graphExits(name, rotation, position)))
                    << name << " position " << position << " rotation " << rotation;
    }
}
