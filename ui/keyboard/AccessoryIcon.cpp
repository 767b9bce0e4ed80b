#include "keyboard/AccessoryIcon.h"

#include <QPainter>
#include <QPainterPath>
#include <QPalette>
#include <QtMath>

namespace stellwerk::ui {
namespace {

using Kind = AccessoryIcon::Kind;

const QColor Red{0xd0, 0x36, 0x36};
const QColor Green{0x2e, 0xa0, 0x4e};
const QColor Yellow{0xe8, 0xb4, 0x1c};
const QColor White{0xf4, 0xf4, 0xf0};
const QColor Unlit{0x55, 0x55, 0x55};

// The icons are drawn in a 100 x 100 square centred in the box.
void useUnitSquare(QPainter& painter, const QRectF& box) {
    const double side = std::min(box.width(), box.height());
    painter.translate(box.center() - QPointF(side / 2, side / 2));
    painter.scale(side / 100.0, side / 100.0);
    painter.setRenderHint(QPainter::Antialiasing);
}

// The track a position sets: thick in the text colour; the other legs thin and faded.
QPen trackPen(const QPalette& palette, bool set) {
    QColor colour = palette.color(QPalette::Text);
    if (!set)
        colour.setAlphaF(0.3f);
    QPen pen(colour, set ? 9 : 6);
    pen.setCapStyle(Qt::FlatCap);
    return pen;
}

void lamp(QPainter& painter, const QPointF& centre, double radius, const QColor& colour, bool lit) {
    painter.setPen(QPen(QColor(0x20, 0x20, 0x20), 1.5));
    painter.setBrush(lit ? colour : Unlit);
    painter.drawEllipse(centre, radius, radius);
}

// Hp2-only signals show Hp2 under position 1.
int aspectOf(Kind kind, int position) {
    if ((kind == Kind::LightSignalHp02 || kind == Kind::SemaphoreHp02) && position == 1)
        return 3;
    return position;
}

struct TypeKind {
    const char* prefix;
    Kind kind;
};

// Longest prefixes first where one type's name starts another's.
constexpr TypeKind TypeKinds[] = {
    {"linksweiche", Kind::LeftTurnout},
    {"rechtsweiche", Kind::RightTurnout},
    {"y_weiche", Kind::YTurnout},
    {"dreiwegweiche", Kind::ThreeWayTurnout},
    {"DKW 2", Kind::DoubleSlipTwoDrives},
    {"DKW", Kind::DoubleSlip},
    {"lichtsignal_HP02", Kind::LightSignalHp02},
    {"lichtsignal_SH01", Kind::ShuntSignal},
    {"urc_lichtsignal_SH01", Kind::ShuntSignal},
    {"formsignal_SH01", Kind::ShuntSignal},
    {"formsignal_HP02", Kind::SemaphoreHp02},
    {"formsignal", Kind::Semaphore},
    {"lichtsignal", Kind::LightSignal},
    {"urc_lichtsignal", Kind::LightSignal},
    {"entkupplungsgleis", Kind::Uncoupler},
    {"k84", Kind::Output},
    {"drehscheibe", Kind::Turntable},
    {"digitaldrehscheibe", Kind::Turntable},
    {"schiebebuehne", Kind::TransferTable},
};

} // namespace

AccessoryIcon::Kind AccessoryIcon::kindOf(const QString& type) {
    for (const TypeKind& entry : TypeKinds)
        if (type.startsWith(QLatin1String(entry.prefix)))
            return entry.kind;
    return Kind::Lamp;
}

QColor AccessoryIcon::positionColour(int position) {
    switch (position) {
    case 0:
        return Red;
    case 1:
        return Green;
    case 2:
        return Yellow;
    default:
        return White;
    }
}

QString AccessoryIcon::positionName(Kind kind, int position) {
    if (position < 0)
        return tr("unknown");
    switch (kind) {
    case Kind::LeftTurnout:
    case Kind::RightTurnout:
    case Kind::DoubleSlip:
        return position == 1 ? tr("Straight") : tr("Diverging");
    case Kind::YTurnout:
        return position == 1 ? tr("Right") : tr("Left");
    case Kind::ThreeWayTurnout:
        return position == 0 ? tr("Left") : position == 1 ? tr("Straight") : tr("Right");
    case Kind::DoubleSlipTwoDrives: {
        const QString names[] = {tr("Diverging"), tr("Straight"), tr("Straight, diverging"),
                                 tr("Diverging, straight")};
        return names[std::clamp(position, 0, 3)];
    }
    case Kind::LightSignal:
    case Kind::LightSignalHp02:
    case Kind::Semaphore:
    case Kind::SemaphoreHp02: {
        const int aspect = aspectOf(kind, position);
        return aspect == 0 ? tr("Hp0") : aspect == 1 ? tr("Hp1") : aspect == 2 ? tr("Sh1") : tr("Hp2");
    }
    case Kind::ShuntSignal:
        return position == 1 ? tr("Sh1") : tr("Sh0");
    case Kind::Uncoupler:
        return position == 1 ? tr("Uncouple") : tr("Rest");
    case Kind::Output:
        return position == 1 ? tr("On") : tr("Off");
    case Kind::Turntable:
    case Kind::TransferTable:
        return tr("Track %1").arg(position + 1);
    case Kind::Plain:
    case Kind::Lamp:
        break;
    }
    return position == 1 ? tr("Green") : tr("Red");
}

void AccessoryIcon::paint(QPainter& painter, const QRectF& box, Kind kind, int position,
                          const QPalette& palette) {
    painter.save();
    useUnitSquare(painter, box);
    switch (kind) {
    case Kind::LeftTurnout:
    case Kind::RightTurnout:
    case Kind::YTurnout:
    case Kind::ThreeWayTurnout:
        paintTurnout(painter, kind, position, palette);
        break;
    case Kind::DoubleSlip:
    case Kind::DoubleSlipTwoDrives:
        paintDoubleSlip(painter, kind, position, palette);
        break;
    case Kind::LightSignal:
    case Kind::LightSignalHp02:
    case Kind::ShuntSignal:
        paintLightSignal(painter, kind, position, palette);
        break;
    case Kind::Semaphore:
    case Kind::SemaphoreHp02:
        paintSemaphore(painter, aspectOf(kind, position), palette);
        break;
    case Kind::Uncoupler:
        paintUncoupler(painter, position, palette);
        break;
    case Kind::Turntable:
    case Kind::TransferTable:
        paintTurntable(painter, kind, position, palette);
        break;
    case Kind::Plain:
    case Kind::Lamp:
    case Kind::Output:
        paintLamps(painter, kind, position, palette);
        break;
    }
    painter.restore();
}

// The straight track from left to right, the legs branching off at the points (x 30).
void AccessoryIcon::paintTurnout(QPainter& painter, Kind kind, int position, const QPalette& palette) {
    const QPointF points(30, 50);
    const QLineF straight(points, QPointF(96, 50));
    const QLineF up(points, QPointF(90, 16));
    const QLineF down(points, QPointF(90, 84));
    struct Leg {
        QLineF line;
        bool present;
        bool set;
    };
    const bool three = kind == Kind::ThreeWayTurnout;
    const bool y = kind == Kind::YTurnout;
    const Leg legs[] = {
        {straight, !y, position == 1},
        {up, kind != Kind::RightTurnout, position == 0},
        {down, kind != Kind::LeftTurnout,
         three ? position == 2
         : y   ? position == 1
               : position == 0},
    };
    for (const Leg& leg : legs)
        if (leg.present && !leg.set) {
            painter.setPen(trackPen(palette, false));
            painter.drawLine(leg.line);
        }
    painter.setPen(trackPen(palette, true));
    painter.drawLine(QLineF(QPointF(4, 50), points));
    for (const Leg& leg : legs)
        if (leg.present && leg.set)
            painter.drawLine(leg.line);
}

// Two tracks crossing; the slips join them. Straight sets both straight tracks, diverging both slips.
void AccessoryIcon::paintDoubleSlip(QPainter& painter, Kind kind, int position, const QPalette& palette) {
    const QLineF first(QPointF(4, 50), QPointF(96, 50));
    const QLineF second(QPointF(8, 82), QPointF(92, 18));
    QPainterPath upperSlip(QPointF(4, 50));
    upperSlip.cubicTo(QPointF(50, 50), QPointF(60, 34), QPointF(92, 18));
    QPainterPath lowerSlip(QPointF(8, 82));
    lowerSlip.cubicTo(QPointF(40, 66), QPointF(50, 50), QPointF(96, 50));
    bool straightFirst = position == 1;
    bool straightSecond = position == 1;
    if (kind == Kind::DoubleSlipTwoDrives && position >= 2) {
        straightFirst = position == 2;
        straightSecond = position == 3;
    }
    painter.setBrush(Qt::NoBrush);
    painter.setPen(trackPen(palette, straightFirst));
    painter.drawLine(first);
    painter.setPen(trackPen(palette, straightSecond));
    painter.drawLine(second);
    painter.setPen(trackPen(palette, !straightFirst));
    painter.drawPath(upperSlip);
    painter.setPen(trackPen(palette, !straightSecond));
    painter.drawPath(lowerSlip);
}

// A mast with a dark screen: red, green and yellow lamps, two white ones below for Sh1. A shunt signal
// is a low screen with two lamps: red side by side (Sh0) or white diagonal (Sh1).
void AccessoryIcon::paintLightSignal(QPainter& painter, Kind kind, int position, const QPalette& palette) {
    painter.setPen(Qt::NoPen);
    painter.setBrush(palette.color(QPalette::Text));
    painter.drawRect(QRectF(46, 60, 8, 38));
    painter.setBrush(QColor(0x26, 0x26, 0x2a));
    QColor outline = palette.color(QPalette::Text);
    outline.setAlphaF(0.35f);
    painter.setPen(QPen(outline, 1.5)); // the screen stays visible on a dark key
    if (kind == Kind::ShuntSignal) {
        painter.drawRoundedRect(QRectF(22, 28, 56, 40), 8, 8);
        const bool sh1 = position == 1;
        lamp(painter, QPointF(36, sh1 ? 56 : 48), 8, sh1 ? White : Red, true);
        lamp(painter, QPointF(64, sh1 ? 40 : 48), 8, sh1 ? White : Red, true);
        return;
    }
    const int aspect = aspectOf(kind, position);
    painter.drawRoundedRect(QRectF(30, 2, 40, 68), 10, 10);
    lamp(painter, QPointF(50, 16), 8, Red, aspect == 0 || aspect == 2);
    lamp(painter, QPointF(50, 36), 8, Green, aspect == 1 || aspect == 3);
    lamp(painter, QPointF(50, 56), 6, Yellow, aspect == 3);
    if (aspect == 2) {
        lamp(painter, QPointF(38, 66), 4, White, true);
        lamp(painter, QPointF(62, 58), 4, White, true);
    }
}

// A mast with one or two arms: level for Hp0, raised for Hp1, both raised for Hp2.
void AccessoryIcon::paintSemaphore(QPainter& painter, int aspect, const QPalette& palette) {
    painter.setPen(Qt::NoPen);
    painter.setBrush(palette.color(QPalette::Text));
    painter.drawRect(QRectF(44, 8, 7, 90));
    const auto arm = [&painter](double y, double degrees) {
        painter.save();
        painter.translate(48, y);
        painter.rotate(-degrees);
        painter.setPen(QPen(QColor(0x20, 0x20, 0x20), 1.5));
        painter.setBrush(Red);
        painter.drawRoundedRect(QRectF(0, -5, 44, 10), 3, 3);
        painter.setBrush(White);
        painter.drawEllipse(QPointF(38, 0), 4, 4);
        painter.restore();
    };
    const bool clear = aspect == 1 || aspect == 3;
    arm(18, clear ? 45 : 0);
    if (aspect == 3)
        arm(42, 45);
    if (aspect == 2)
        lamp(painter, QPointF(30, 70), 5, White, true);
}

// A straight track with the uncoupling ramp between the rails; lit while it is raised.
void AccessoryIcon::paintUncoupler(QPainter& painter, int position, const QPalette& palette) {
    painter.setPen(trackPen(palette, true));
    painter.drawLine(QLineF(4, 38, 96, 38));
    painter.drawLine(QLineF(4, 62, 96, 62));
    painter.setPen(QPen(palette.color(QPalette::Text), 2));
    painter.setBrush(position == 1 ? Yellow : palette.color(QPalette::Base));
    painter.drawRect(QRectF(34, 44, 32, 12));
    if (position == 1) {
        painter.setBrush(Qt::NoBrush);
        painter.setPen(QPen(Yellow, 3));
        painter.drawArc(QRectF(26, 20, 48, 60), 30 * 16, 120 * 16);
        painter.drawArc(QRectF(26, 20, 48, 60), 210 * 16, 120 * 16);
    }
}

// A red and a green lamp (a keyboard number, a plain red/green article) or an output's on/off lamp.
void AccessoryIcon::paintLamps(QPainter& painter, Kind kind, int position, const QPalette& palette) {
    if (kind == Kind::Output) {
        lamp(painter, QPointF(50, 40), 22, Yellow, position == 1);
        painter.setPen(QPen(palette.color(QPalette::Text), 6));
        painter.drawLine(QLineF(40, 70, 60, 70));
        painter.drawLine(QLineF(42, 80, 58, 80));
        return;
    }
    lamp(painter, QPointF(28, 50), 18, Red, position == 0);
    lamp(painter, QPointF(72, 50), 18, Green, position == 1);
}

// A round pit with its bridge pointing at the track of the position, or a transfer table's bridge.
void AccessoryIcon::paintTurntable(QPainter& painter, Kind kind, int position, const QPalette& palette) {
    painter.setPen(QPen(palette.color(QPalette::Text), 3));
    painter.setBrush(Qt::NoBrush);
    if (kind == Kind::TransferTable) {
        painter.drawRect(QRectF(24, 6, 52, 88));
        const double y = 18 + 21.0 * std::clamp(position, 0, 3);
        painter.setPen(trackPen(palette, true));
        painter.drawLine(QLineF(4, y, 96, y));
        return;
    }
    painter.drawEllipse(QPointF(50, 50), 44, 44);
    painter.save();
    painter.translate(50, 50);
    painter.rotate(std::max(position, 0) * 360.0 / 32);
    painter.setPen(trackPen(palette, true));
    painter.drawLine(QLineF(-40, 0, 40, 0));
    painter.setPen(Qt::NoPen);
    painter.setBrush(Yellow);
    painter.drawEllipse(QPointF(36, 0), 6, 6);
    painter.restore();
}

} // namespace stellwerk::ui
