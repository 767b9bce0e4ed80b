#pragma once

#include "trackplan/TrackColors.h"
#include "trackplan/TrackTileLook.h"

#include <QFont>
#include <QPainter>
#include <QPainterPath>
#include <QRectF>

namespace stellwerk::ui::shapes {

// One tile being drawn. After unit() the painter draws in tile units: (0,0) top left, (1,1) bottom right,
// already turned by the tile's rotation, so that every shape is written once in its unrotated form.
struct TileCanvas {
    QPainter& painter;
    QRectF cell;
    const TrackTileLook& look;
    const TrackColors& colors;

    static constexpr double TrackWidth = 0.14;

    void unit();
    void stroke(const QPainterPath& path, const QColor& color, double width = TrackWidth);
    void stroke(const QPainterPath& path, QPen pen); // the pen's width in tile units
    void line(QPointF from, QPointF to, const QColor& color, double width = TrackWidth);
    void fill(const QPainterPath& path, const QColor& color, const QColor& outline, double width = 0.04);
    // The track colour; the occupied colour on an occupied contact, the highlight on a set route.
    QColor trackColor() const;
    // The colour of a leg: full when the accessory stands at `position` or its position is unknown (the
    // highlight when a set route holds it), dim otherwise.
    QColor legColor(int position) const;
};

// The midpoints of the tile's edges.
inline constexpr QPointF West{0.0, 0.5};
inline constexpr QPointF East{1.0, 0.5};
inline constexpr QPointF North{0.5, 0.0};
inline constexpr QPointF South{0.5, 1.0};

// A quarter circle of radius 1/2 around a corner of the tile, from one edge midpoint to the next.
QPainterPath quarter(QPointF corner, double startDegrees, double sweepDegrees);

// Where a label's text goes: the font, the text and its box around the cell's centre, turned by `angle`
// degrees. Labels run beyond their tile, as on the CS2.
struct LabelLayout {
    QFont font;
    QString text;
    QRectF box;
    double angle = 0.0;
};
LabelLayout labelLayout(const QRectF& cell, const TrackTileLook& look, QFont font);

// Track (TrackShapes.cpp)
void straight(TileCanvas& c);
void curve(TileCanvas& c);
void doubleCurve(TileCanvas& c);
void crossing(TileCanvas& c);
void underpass(TileCanvas& c);
void bufferStop(TileCanvas& c);
void tunnel(TileCanvas& c);
// Turnouts (TurnoutShapes.cpp)
void leftTurnout(TileCanvas& c);
void rightTurnout(TileCanvas& c);
void yTurnout(TileCanvas& c);
void threeWayTurnout(TileCanvas& c);
void doubleSlip(TileCanvas& c);
void threeWaySlip(TileCanvas& c);
void scissors(TileCanvas& c);
// Signals (SignalShapes.cpp)
void lightSignal(TileCanvas& c);
// Where lamp `lamp` of a light signal with `lamps` lamps sits, in tile units (rotation 0).
QPointF lampCentre(std::size_t lamp, std::size_t lamps);
void formSignal(TileCanvas& c);
void shuntingSignal(TileCanvas& c);
// Everything else (FeatureShapes.cpp)
void contact(TileCanvas& c);
void contactCurve(TileCanvas& c);
void contactDoubleCurve(TileCanvas& c);
void pageLink(TileCanvas& c);
void routeButton(TileCanvas& c);
void label(TileCanvas& c);
void uncoupler(TileCanvas& c);
void outputButton(TileCanvas& c);
void relay(TileCanvas& c);
void lamp(TileCanvas& c);
void levelCrossing(TileCanvas& c);
void turntable(TileCanvas& c);
void transferTable(TileCanvas& c);
void unknown(TileCanvas& c);

} // namespace stellwerk::ui::shapes
