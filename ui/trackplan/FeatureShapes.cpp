// Everything on the plan that is not plain track, a turnout or a signal: contacts, buttons, labels,
// uncouplers, outputs, lamps, level crossings, turntables and transfer tables.
#include "trackplan/TrackShapes.h"

#include <QFont>
#include <QFontMetricsF>

namespace stellwerk::ui::shapes {
namespace {

// The contact's marker beside the rail: a bar on the north side, filled when a train occupies it.
void contactMarker(TileCanvas& c, QPointF centre) {
    QPainterPath marker;
    marker.addRoundedRect(QRectF(centre.x() - 0.2, centre.y() - 0.09, 0.4, 0.18), 0.05, 0.05);
    c.fill(marker, c.look.occupied ? c.colors.occupied : c.colors.background, c.trackColor(), 0.05);
}

// The number in a tile's type word after the last '_' ("drehscheibe_dig_7" -> 7), 0 when there is none.
int typeSuffix(const QString& type) {
    const qsizetype underscore = type.lastIndexOf(QLatin1Char('_'));
    return underscore < 0 ? 0 : type.mid(underscore + 1).toInt();
}

// A wire from the west edge to a symbol, which gives round symbols a direction.
void wire(TileCanvas& c, double to) {
    c.line(West, {to, 0.5}, c.colors.dim, 0.05);
}

} // namespace

void contact(TileCanvas& c) {
    c.unit();
    c.line(West, East, c.trackColor());
    contactMarker(c, {0.5, 0.26});
}

void contactCurve(TileCanvas& c) {
    c.unit();
    c.stroke(quarter({1, 1}, 90, 90), c.trackColor());
    contactMarker(c, {0.52, 0.52});
}

void contactDoubleCurve(TileCanvas& c) {
    c.unit();
    c.stroke(quarter({1, 1}, 90, 90), c.trackColor());
    c.stroke(quarter({0, 0}, 270, 90), c.trackColor());
    contactMarker(c, {0.5, 0.5});
}

void pageLink(TileCanvas& c) {
    c.unit();
    c.line(West, {0.45, 0.5}, c.colors.track);
    QPainterPath arrow({0.42, 0.22});
    arrow.lineTo(0.9, 0.5);
    arrow.lineTo(0.42, 0.78);
    arrow.closeSubpath();
    c.fill(arrow, c.colors.highlight, c.colors.track, 0.03);
}

void routeButton(TileCanvas& c) {
    c.unit();
    QPainterPath button;
    button.addRoundedRect(QRectF(0.1, 0.18, 0.8, 0.64), 0.14, 0.14);
    // Running: filled in the highlight colour; set: ringed in it.
    c.fill(button, c.look.running ? c.colors.highlight : c.colors.button,
           c.look.onRoute ? c.colors.highlight : c.colors.track, c.look.onRoute ? 0.1 : 0.05);
    QPainterPath arrow({0.38, 0.32}); // where the route leads
    arrow.lineTo(0.66, 0.5);
    arrow.lineTo(0.38, 0.68);
    arrow.closeSubpath();
    c.fill(arrow, c.look.running ? c.colors.background : c.colors.track, QColor());
}

LabelLayout labelLayout(const QRectF& cell, const TrackTileLook& look, QFont font) {
    const int quarterTurns = look.rotation & 3;
    LabelLayout layout;
    layout.angle = quarterTurns % 2 ? -90.0 * ((quarterTurns == 1) ? 1 : -1) : 0.0;
    font.setPixelSize(std::max(6, int(cell.height() * 0.42)));
    layout.font = font;
    layout.text = look.text.isEmpty() ? QStringLiteral("T") : look.text;
    const double half = cell.width() / 2;
    // Rotation 2 ends at its tile instead of starting there.
    const double width = QFontMetricsF(font).horizontalAdvance(layout.text);
    const double left = quarterTurns == 2 ? half - width : -half;
    layout.box = QRectF(left, -half, width + 1, 2 * half);
    return layout;
}

void label(TileCanvas& c) {
    const LabelLayout layout = labelLayout(c.cell, c.look, c.painter.font());
    c.painter.translate(c.cell.center());
    c.painter.rotate(layout.angle);
    c.painter.setFont(layout.font);
    c.painter.setPen(c.colors.text);
    c.painter.drawText(layout.box, Qt::AlignVCenter | Qt::AlignLeft, layout.text);
}

void uncoupler(TileCanvas& c) {
    c.unit();
    c.line(West, East, c.trackColor());
    QPainterPath magnet;
    magnet.addRect(QRectF(0.3, 0.2, 0.4, 0.22));
    const bool active = c.look.position == 1;
    c.fill(magnet, active ? c.colors.yellow : c.colors.background, c.colors.track, 0.05);
    if (c.look.type.endsWith(QLatin1String("_1")))
        c.line({0.5, 0.24}, {0.5, 0.38}, c.colors.track, 0.05);
}

void outputButton(TileCanvas& c) {
    c.unit();
    wire(c, 0.2);
    const QString& type = c.look.type;
    const bool red = type != QLatin1String("std_gruen");
    const bool green = type != QLatin1String("std_rot");
    QPainterPath frame;
    frame.addRoundedRect(QRectF(0.2, 0.2, 0.6, 0.6), 0.1, 0.1);
    c.fill(frame, c.colors.button, c.colors.track, 0.05);
    const auto half = [&c](QRectF rect, const QColor& color, int position) {
        QPainterPath light;
        light.addEllipse(rect);
        c.fill(light, c.look.position == position ? color : c.colors.dim, QColor());
    };
    if (red && green) {
        half(QRectF(0.27, 0.35, 0.22, 0.3), c.colors.red, 0);
        half(QRectF(0.51, 0.35, 0.22, 0.3), c.colors.green, 1);
    } else {
        half(QRectF(0.33, 0.33, 0.34, 0.34), red ? c.colors.red : c.colors.green, red ? 0 : 1);
    }
}

void relay(TileCanvas& c) {
    c.unit();
    wire(c, 0.2);
    QPainterPath box;
    box.addRect(QRectF(0.2, 0.25, 0.6, 0.5));
    c.fill(box, c.colors.button, c.colors.track, 0.05);
    const bool closed = c.look.position == 1;
    c.line({0.32, 0.6}, closed ? QPointF(0.68, 0.6) : QPointF(0.62, 0.36),
           closed ? c.colors.green : c.colors.track, 0.06);
    if (c.look.type == QLatin1String("k84_doppelt"))
        c.line({0.32, 0.4}, {0.5, 0.4}, c.colors.track, 0.05);
}

void lamp(TileCanvas& c) {
    c.unit();
    wire(c, 0.26);
    const QString& type = c.look.type;
    QColor light = c.colors.yellow;
    if (type.endsWith(QLatin1String("_rt")))
        light = c.colors.red;
    else if (type.endsWith(QLatin1String("_gn")))
        light = c.colors.green;
    else if (type.endsWith(QLatin1String("_bl")))
        light = QColor(66, 133, 244);
    QPainterPath bulb;
    bulb.addEllipse(QPointF(0.5, 0.5), 0.24, 0.24);
    c.fill(bulb, c.look.position == 1 ? light : c.colors.background, c.colors.track, 0.05);
    c.line({0.33, 0.33}, {0.67, 0.67}, c.colors.track, 0.04);
    c.line({0.33, 0.67}, {0.67, 0.33}, c.colors.track, 0.04);
}

void levelCrossing(TileCanvas& c) {
    c.unit();
    c.line({0.3, 0}, {0.3, 1}, c.colors.dim, 0.04); // the road's edges
    c.line({0.7, 0}, {0.7, 1}, c.colors.dim, 0.04);
    c.line(West, East, c.trackColor());
    const bool closed = c.look.position == 1;
    const QPointF post(0.22, 0.18);
    c.line(post, closed ? QPointF(0.78, 0.18) : QPointF(0.22, -0.0), closed ? c.colors.red : c.colors.track,
           0.07);
    QPainterPath hub;
    hub.addEllipse(post, 0.05, 0.05);
    c.fill(hub, c.colors.track, QColor());
}

void turntable(TileCanvas& c) {
    c.unit();
    c.line(West, {0.1, 0.5}, c.colors.track);
    QPainterPath pit;
    pit.addEllipse(QPointF(0.5, 0.5), 0.42, 0.42);
    c.fill(pit, c.colors.background, c.colors.track, 0.05);
    const int steps = c.look.type.startsWith(QLatin1String("drehscheibe_alt")) ? 8 : 32;
    const int stop = c.look.position >= 0 ? c.look.position : typeSuffix(c.look.type);
    c.painter.save();
    c.painter.translate(0.5, 0.5);
    c.painter.rotate(-360.0 * (stop % steps) / steps);
    c.line({-0.38, 0}, {0.38, 0}, c.colors.track);
    c.line({0.26, -0.08}, {0.26, 0.08}, c.colors.track, 0.04); // the bridge's house marks its end
    c.painter.restore();
}

void transferTable(TileCanvas& c) {
    c.unit();
    c.line(West, {0.12, 0.5}, c.colors.track);
    QPainterPath pit;
    pit.addRect(QRectF(0.12, 0.06, 0.76, 0.88));
    c.fill(pit, c.colors.background, c.colors.track, 0.05);
    const int stop = c.look.position >= 0 ? c.look.position : typeSuffix(c.look.type);
    const double y = 0.2 + 0.2 * (stop % 4);
    c.line({0.16, y}, {0.84, y}, c.colors.track, 0.12);
}

void unknown(TileCanvas& c) {
    c.unit();
    QPainterPath box;
    box.addRect(QRectF(0.12, 0.12, 0.76, 0.76));
    c.stroke(box, QPen(c.colors.dim, 0.04, Qt::DashLine));
    c.line(West, {0.12, 0.5}, c.colors.dim, 0.06);
    QFont font = c.painter.font();
    font.setPixelSize(50);
    QPainterPath mark;
    mark.addText(0, 0, font, QStringLiteral("?"));
    const QRectF bounds = mark.boundingRect();
    const double scale = 0.5 / bounds.height();
    QTransform place;
    place.translate(0.5, 0.5);
    place.scale(scale, scale);
    place.translate(-bounds.center().x(), -bounds.center().y());
    c.fill(place.map(mark), c.colors.dim, QColor());
}

} // namespace stellwerk::ui::shapes
