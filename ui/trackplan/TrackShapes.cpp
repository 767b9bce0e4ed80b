// Plain track: drawn unrotated from the west edge, the painter turns it.
#include "trackplan/TrackShapes.h"

namespace stellwerk::ui::shapes {

void straight(TileCanvas& c) {
    c.unit();
    c.line(West, East, c.trackColor());
}

void curve(TileCanvas& c) {
    c.unit();
    c.stroke(quarter({1, 1}, 90, 90), c.trackColor()); // east to south
}

void doubleCurve(TileCanvas& c) {
    c.unit();
    c.stroke(quarter({1, 1}, 90, 90), c.trackColor());  // east to south
    c.stroke(quarter({0, 0}, 270, 90), c.trackColor()); // west to north
}

void crossing(TileCanvas& c) {
    c.unit();
    c.line(West, East, c.trackColor());
    c.line(North, South, c.trackColor());
}

void underpass(TileCanvas& c) {
    c.unit();
    c.line(North, {0.5, 0.22}, c.trackColor());
    c.line({0.5, 0.78}, South, c.trackColor());
    c.line(West, East, c.trackColor());
    for (const double y : {0.3, 0.7}) { // the bridge's parapets over the lower track
        QPainterPath parapet({0.18, y + (y < 0.5 ? -0.08 : 0.08)});
        parapet.lineTo(0.28, y);
        parapet.lineTo(0.72, y);
        parapet.lineTo(0.82, y + (y < 0.5 ? -0.08 : 0.08));
        c.stroke(parapet, c.colors.track, 0.05);
    }
}

void bufferStop(TileCanvas& c) {
    c.unit();
    c.line(West, {0.68, 0.5}, c.trackColor());
    c.line({0.72, 0.24}, {0.72, 0.76}, c.trackColor(), 0.12);
}

void tunnel(TileCanvas& c) {
    c.unit();
    c.line(West, {0.3, 0.5}, c.trackColor());
    c.line({0.7, 0.5}, East, c.trackColor());
    QPainterPath inside({0.3, 0.5});
    inside.lineTo(0.7, 0.5);
    c.stroke(inside, QPen(c.colors.dim, 0.08, Qt::DashLine, Qt::FlatCap));
    for (const double x : {0.3, 0.7}) { // the portals
        QPainterPath portal({x + (x < 0.5 ? -0.1 : 0.1), 0.2});
        portal.lineTo(x, 0.28);
        portal.lineTo(x, 0.72);
        portal.lineTo(x + (x < 0.5 ? -0.1 : 0.1), 0.8);
        c.stroke(portal, c.colors.track, 0.06);
    }
}

} // namespace stellwerk::ui::shapes
