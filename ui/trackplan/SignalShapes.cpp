// Signals: the track runs west to east and the signal stands beside it on the south side, facing the
// trains that come from the west. Positions follow the CS2: 0 stop (Hp0), 1 proceed (Hp1), 2 slow
// (Hp2), 3 shunting (Sh1) on signals that have it.
#include "trackplan/TrackShapes.h"

#include <algorithm>
#include <vector>

namespace stellwerk::ui::shapes {
namespace {

enum class Lamp { Red, Green, Yellow, White };

// The distance between lamp centres (in tiles) for one, two, three and four lamps.
constexpr double LampSteps[] = {0.3, 0.3, 0.25, 0.19};

std::vector<Lamp> lampsOf(const QString& type) {
    const bool shunting = type.endsWith(QLatin1Char('s'));
    std::vector<Lamp> lamps{Lamp::Red};
    if (!type.contains(QLatin1String("hp02")))
        lamps.push_back(Lamp::Green);
    if (type.contains(QLatin1String("hp02")) || type.contains(QLatin1String("hp012")))
        lamps.push_back(Lamp::Yellow);
    if (shunting)
        lamps.push_back(Lamp::White);
    return lamps;
}

QColor lampColor(const TrackColors& colors, Lamp lamp) {
    switch (lamp) {
    case Lamp::Red:
        return colors.red;
    case Lamp::Green:
        return colors.green;
    case Lamp::Yellow:
        return colors.yellow;
    case Lamp::White:
        break;
    }
    return colors.white;
}

// The colour a signal shows in its position: red at stop, green otherwise, the track's when unknown.
QColor aspectColor(const TileCanvas& c) {
    if (c.look.position < 0)
        return c.colors.track;
    return c.look.position == 0 ? c.colors.red : c.colors.green;
}

void mast(TileCanvas& c, double x, double top) {
    c.line({x, top}, {x, 0.95}, c.colors.track, 0.05);
    c.line({x - 0.07, 0.95}, {x + 0.07, 0.95}, c.colors.track, 0.05);
}

} // namespace

// The head fills the lower half of the tile so that the lit lamp reads at a glance: a lamp is a fifth of
// the tile across with up to two lamps, smaller with more.
void lightSignal(TileCanvas& c) {
    c.unit();
    c.line(West, East, c.trackColor());
    const std::vector<Lamp> lamps = lampsOf(c.look.type);
    const double step = LampSteps[std::min<std::size_t>(lamps.size(), 4) - 1];
    mast(c, 0.12, 0.62);
    QPainterPath head;
    head.addRoundedRect(QRectF(0.2, 0.56, 0.06 + step * double(lamps.size()), 0.4), 0.08, 0.08);
    c.fill(head, c.colors.background, c.colors.track, 0.04);
    for (std::size_t i = 0; i < lamps.size(); ++i) {
        QColor color = lampColor(c.colors, lamps[i]);
        if (c.look.position < 0)
            color.setAlphaF(0.45f);
        else if (c.look.position != int(i))
            color = c.colors.dim;
        QPainterPath bulb;
        bulb.addEllipse(lampCentre(i, lamps.size()), step * 0.4, step * 0.4);
        c.fill(bulb, color, QColor());
    }
}

QPointF lampCentre(std::size_t lamp, std::size_t lamps) {
    const double step = LampSteps[std::min<std::size_t>(lamps, 4) - 1];
    return {0.23 + step * (0.5 + double(lamp)), 0.76};
}

// A semaphore as large as a light signal's head: a broad arm with a disc at its end, in the aspect's colour,
// level at stop and raised at proceed; the second arm (Hp2) below it. The track is drawn over the arms'
// tips, which a raised arm reaches up to.
void formSignal(TileCanvas& c) {
    c.unit();
    const bool twoArms =
        c.look.type.contains(QLatin1String("hp02")) || c.look.type.contains(QLatin1String("hp012"));
    mast(c, 0.2, 0.58);
    const auto arm = [&c](double y, double length, double width, bool raised) {
        QPainterPath paddle;
        paddle.addRect(QRectF(0, -width / 2, length, width));
        paddle.addEllipse(QPointF(length, 0), width * 0.75, width * 0.75);
        paddle.setFillRule(Qt::WindingFill);
        const QTransform place = QTransform::fromTranslate(0.2, y).rotate(raised ? -40 : 0);
        c.fill(place.map(paddle.simplified()), aspectColor(c), QColor());
        QPainterPath hub;
        hub.addEllipse(QPointF(0.2, y), 0.045, 0.045);
        c.fill(hub, c.colors.track, QColor());
    };
    arm(twoArms ? 0.7 : 0.8, 0.44, 0.14, c.look.position >= 1);
    if (twoArms)
        arm(0.9, 0.36, 0.1, c.look.position == 2);
    c.line(West, East, c.trackColor());
    if (c.look.type.endsWith(QLatin1Char('s'))) {
        QPainterPath lamp;
        lamp.addEllipse(QPointF(0.08, 0.8), 0.05, 0.05);
        c.fill(lamp, c.look.position == 3 ? c.colors.white : c.colors.dim, c.colors.track, 0.02);
    }
}

void shuntingSignal(TileCanvas& c) {
    c.unit();
    c.line(West, East, c.trackColor());
    QPainterPath disc;
    disc.moveTo(0.25, 0.95);
    disc.arcTo(QRectF(0.25, 0.62, 0.4, 0.66), 180, -180);
    disc.closeSubpath();
    c.fill(disc, c.colors.white, c.colors.track, 0.035);
    const QPointF centre(0.45, 0.84);
    const QPointF reach = c.look.position == 1 ? QPointF(0.1, -0.1) : QPointF(0.14, 0);
    c.line(centre - reach, centre + reach, c.look.position < 0 ? c.colors.dim : QColor(Qt::black), 0.05);
}

} // namespace stellwerk::ui::shapes
