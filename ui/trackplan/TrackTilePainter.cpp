#include "trackplan/TrackTilePainter.h"

#include "trackplan/TrackShapes.h"

#include <QPainter>
#include <array>
#include <cmath>
#include <string_view>

namespace stellwerk::ui {
namespace {

using Shape = void (*)(shapes::TileCanvas&);

// One `.typ` word (or, ending in '*', a prefix of words) and the shape that draws it. The first
// match wins, so exact words come before the prefixes that would also match them.
struct ShapeEntry {
    std::string_view type;
    Shape draw;
};

constexpr std::array shapeTable{
    // clang-format off
    ShapeEntry{"gerade", shapes::straight},           ShapeEntry{"bogen", shapes::curve},
    ShapeEntry{"doppelbogen", shapes::doubleCurve},   ShapeEntry{"kreuzung", shapes::crossing},
    ShapeEntry{"unterfuehrung", shapes::underpass},   ShapeEntry{"prellbock", shapes::bufferStop},
    ShapeEntry{"tunnel", shapes::tunnel},             ShapeEntry{"linksweiche", shapes::leftTurnout},
    ShapeEntry{"rechtsweiche", shapes::rightTurnout}, ShapeEntry{"yweiche", shapes::yTurnout},
    ShapeEntry{"dreiwegweiche", shapes::threeWayTurnout}, ShapeEntry{"dkweiche*", shapes::doubleSlip},
    ShapeEntry{"dkw3_*", shapes::threeWaySlip},       ShapeEntry{"hosentraeger", shapes::scissors},
    ShapeEntry{"signal_sh01", shapes::shuntingSignal}, ShapeEntry{"signal_f_*", shapes::formSignal},
    ShapeEntry{"signal*", shapes::lightSignal},       ShapeEntry{"s88kontakt", shapes::contact},
    ShapeEntry{"s88bogen", shapes::contactCurve},     ShapeEntry{"s88doppelbogen", shapes::contactDoubleCurve},
    ShapeEntry{"pfeil", shapes::pageLink},            ShapeEntry{"fahrstrasse", shapes::routeButton},
    ShapeEntry{"text", shapes::label},                ShapeEntry{"entkuppler*", shapes::uncoupler},
    ShapeEntry{"std_*", shapes::outputButton},        ShapeEntry{"k84_*", shapes::relay},
    ShapeEntry{"lampe*", shapes::lamp},               ShapeEntry{"bahnschranke", shapes::levelCrossing},
    ShapeEntry{"drehscheibe*", shapes::turntable},    ShapeEntry{"schiebebuehne_*", shapes::transferTable},
    // clang-format on
};

bool matches(std::string_view pattern, std::string_view type) {
    if (pattern.ends_with('*'))
        return type.starts_with(pattern.substr(0, pattern.size() - 1));
    return pattern == type;
}

Shape shapeFor(const QString& type) {
    if (type.isEmpty())
        return shapes::label; // an element without `.typ` is a text (TrackElement::elementType)
    if (type == QLatin1String("leer"))
        return nullptr;
    const QByteArray word = type.toLatin1();
    const std::string_view name(word.constData(), std::size_t(word.size()));
    for (const ShapeEntry& entry : shapeTable)
        if (matches(entry.type, name))
            return entry.draw;
    return shapes::unknown;
}

} // namespace

void TrackTilePainter::paint(QPainter& painter, const QRectF& cell, const TrackTileLook& look,
                             const TrackColors& colors) {
    const Shape draw = shapeFor(look.type);
    if (!draw)
        return;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    shapes::TileCanvas canvas{painter, cell, look, colors};
    draw(canvas);
    painter.restore();
}

bool TrackTilePainter::draws(const TrackTileLook& look) {
    return shapeFor(look.type) != nullptr;
}

bool TrackTilePainter::usesFont(const TrackTileLook& look) {
    const Shape draw = shapeFor(look.type);
    return draw == shapes::label || draw == shapes::unknown;
}

QRectF TrackTilePainter::area(const QRectF& cell, const TrackTileLook& look, const QFont& font) {
    if (shapeFor(look.type) != shapes::label)
        return cell;
    const shapes::LabelLayout layout = shapes::labelLayout(cell, look, font);
    return QTransform()
        .translate(cell.center().x(), cell.center().y())
        .rotate(layout.angle)
        .mapRect(layout.box);
}

namespace shapes {

void TileCanvas::unit() {
    painter.translate(cell.center());
    painter.rotate(-90.0 * (look.rotation & 3)); // counter-clockwise on screen
    painter.scale(cell.width(), cell.height());
    painter.translate(-0.5, -0.5);
}

void TileCanvas::stroke(const QPainterPath& path, const QColor& color, double width) {
    stroke(path, QPen(color, width, Qt::SolidLine, Qt::FlatCap, Qt::RoundJoin));
}

// Qt flattens curves for the stroker in the path's own coordinates; in tile units (0..1) that yields
// curves of hundreds of segments. Mapped to pixels first, an arc is drawn six times faster.
void TileCanvas::stroke(const QPainterPath& path, QPen pen) {
    const QTransform world = painter.worldTransform();
    pen.setWidthF(pen.widthF() * std::sqrt(std::abs(world.determinant())));
    painter.save();
    painter.resetTransform();
    painter.strokePath(world.map(path), pen);
    painter.restore();
}

void TileCanvas::line(QPointF from, QPointF to, const QColor& color, double width) {
    QPainterPath path(from);
    path.lineTo(to);
    stroke(path, color, width);
}

void TileCanvas::fill(const QPainterPath& path, const QColor& color, const QColor& outline, double width) {
    const QTransform world = painter.worldTransform();
    const double scale = std::sqrt(std::abs(world.determinant()));
    painter.save();
    painter.resetTransform();
    painter.setPen(outline.isValid() ? QPen(outline, width * scale) : QPen(Qt::NoPen));
    painter.setBrush(color);
    painter.drawPath(world.map(path));
    painter.restore();
}

QColor TileCanvas::trackColor() const {
    return look.occupied ? colors.occupied : look.onRoute ? colors.highlight : colors.track;
}

QColor TileCanvas::legColor(int position) const {
    if (look.position >= 0 && look.position != position)
        return colors.dim;
    return look.onRoute && look.position >= 0 ? colors.highlight : colors.track;
}

QPainterPath quarter(QPointF corner, double startDegrees, double sweepDegrees) {
    const double radians = startDegrees * M_PI / 180.0;
    QPainterPath path(corner + QPointF(0.5 * std::cos(radians), -0.5 * std::sin(radians)));
    path.arcTo(QRectF(corner.x() - 0.5, corner.y() - 0.5, 1.0, 1.0), startDegrees, sweepDegrees);
    return path;
}

} // namespace shapes
} // namespace stellwerk::ui
