// Turnouts and slips. Unrotated, a turnout's points are at the south edge and its straight leg runs
// north, as the CS2's own pages draw them (karben.cs2: rotation 1 and 3 lie along the tracks).
// Position 0 is the diverging leg, 1 the straight one, as on the CS2's keyboard (red/round, green/straight).
#include "trackplan/TrackShapes.h"

#include <initializer_list>

namespace stellwerk::ui::shapes {
namespace {

QPainterPath segment(QPointF from, QPointF to) {
    QPainterPath path(from);
    path.lineTo(to);
    return path;
}

const QPainterPath& toWest() {
    static const QPainterPath path = quarter({0, 1}, 0, 90); // south to west
    return path;
}

const QPainterPath& toEast() {
    static const QPainterPath path = quarter({1, 1}, 180, -90); // south to east
    return path;
}

// One leg of a turnout and the positions that set it.
struct Leg {
    QPainterPath path;
    std::initializer_list<int> positions;
};

bool isSet(const TileCanvas& c, std::initializer_list<int> positions) {
    for (const int position : positions)
        if (c.look.position == position)
            return true;
    return false;
}

// Draws the legs the accessory is not set to first, dimmed, then the set ones over them (in the
// highlight colour while a set route holds the turnout).
void drawLegs(TileCanvas& c, std::initializer_list<Leg> legs) {
    c.unit();
    const bool known = c.look.position >= 0;
    for (const Leg& leg : legs)
        if (known && !isSet(c, leg.positions))
            c.stroke(leg.path, c.colors.dim, TileCanvas::TrackWidth * 0.8);
    for (const Leg& leg : legs)
        if (!known || isSet(c, leg.positions))
            c.stroke(leg.path, known && c.look.onRoute ? c.colors.highlight : c.colors.track);
}

} // namespace

void leftTurnout(TileCanvas& c) {
    drawLegs(c, {{toWest(), {0}}, {segment(South, North), {1}}});
}

void rightTurnout(TileCanvas& c) {
    drawLegs(c, {{toEast(), {0}}, {segment(South, North), {1}}});
}

void yTurnout(TileCanvas& c) {
    drawLegs(c, {{toWest(), {0}}, {toEast(), {1}}});
}

void threeWayTurnout(TileCanvas& c) {
    drawLegs(c, {{toWest(), {0}}, {segment(South, North), {1}}, {toEast(), {2}}});
}

void doubleSlip(TileCanvas& c) {
    const QPainterPath northEast = quarter({1, 0}, 180, 90); // north to east
    if (c.look.type == QLatin1String("dkweiche_2")) {        // two drives, four routes
        drawLegs(c, {{toWest(), {0, 2}},
                     {northEast, {0, 3}},
                     {segment(South, North), {1, 3}},
                     {segment(West, East), {1, 2}}});
        return;
    }
    drawLegs(c,
             {{toWest(), {0}}, {northEast, {0}}, {segment(South, North), {1}}, {segment(West, East), {1}}});
}

void threeWaySlip(TileCanvas& c) {
    const bool left = c.look.type.startsWith(QLatin1String("dkw3_li"));
    drawLegs(c,
             {{left ? toWest() : toEast(), {0}}, {segment(South, North), {1}}, {segment(West, East), {2}}});
}

void scissors(TileCanvas& c) {
    drawLegs(c, {{segment({0, 0}, {1, 1}), {0}}, {segment({0, 1}, {1, 0}), {0}}, {segment(West, East), {1}}});
}

} // namespace stellwerk::ui::shapes
