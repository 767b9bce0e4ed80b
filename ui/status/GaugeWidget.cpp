#include "status/GaugeWidget.h"

#include <QLocale>
#include <QPaintEvent>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

namespace stellwerk::ui {
namespace {

constexpr double StartAngle = 225.0; // the scale's start, lower left
constexpr double Sweep = 270.0;      // clockwise to the lower right
const QColor OverloadRed{0xc8, 0x2c, 0x2c};

// The step between labelled ticks: 1, 2, 2.5 or 5 times a power of ten that divides the scale into 4 to
// 10 parts (closest to 6), so that both ends carry a label; else the nicest step near a sixth.
double tickStep(double range) {
    double best = 0;
    double bestDistance = 1e9;
    const double magnitude = std::pow(10.0, std::floor(std::log10(range / 6.0)));
    for (const double power : {magnitude / 10, magnitude, magnitude * 10})
        for (const double base : {1.0, 2.0, 2.5, 5.0}) {
            const double step = base * power;
            const double parts = range / step;
            if (parts < 3.99 || parts > 10.01 || std::abs(parts - std::round(parts)) > 1e-6)
                continue;
            if (std::abs(parts - 6) < bestDistance) {
                bestDistance = std::abs(parts - 6);
                best = step;
            }
        }
    if (best > 0)
        return best;
    const double rough = range / 6.0;
    const double n = rough / magnitude;
    return (n < 1.5 ? 1 : n < 3 ? 2 : n < 7 ? 5 : 10) * magnitude;
}

int decimalsOf(double step) {
    for (int decimals = 0; decimals < 4; ++decimals)
        if (std::abs(step * std::pow(10.0, decimals) - std::round(step * std::pow(10.0, decimals))) < 1e-6)
            return decimals;
    return 3;
}

// The description's 2-bit colour as a calm instrument colour that reads on light and dark backgrounds.
QColor zoneColour(const model::StatusChannel::Zone& zone) {
    QColor colour(zone.red * 85, zone.green * 85, zone.blue * 85);
    int h = 0, s = 0, v = 0;
    colour.getHsv(&h, &s, &v);
    if (h < 0) // grey
        return QColor::fromHsv(0, 0, std::max(v, 110));
    return QColor::fromHsv(h, std::min(s, 170), 205);
}

QPointF onCircle(const QPointF& centre, double radius, double degrees) {
    const double radians = qDegreesToRadians(degrees);
    return centre + QPointF(radius * std::cos(radians), -radius * std::sin(radians));
}

} // namespace

GaugeWidget::GaugeWidget(QWidget* parent) : QWidget(parent) {
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Preferred);
}

void GaugeWidget::setChannel(const model::StatusChannel& channel) {
    m_unit = channel.unit() == QStringLiteral("C") ? QStringLiteral("°C") : channel.unit();
    m_minimum = channel.minimum();
    m_maximum = channel.maximum() > m_minimum ? channel.maximum() : m_minimum + 1;
    m_decimals = channel.decimals();
    m_zones = channel.zones();
    m_value = channel.value();
    m_stale = channel.stale();
    setToolTip(m_stale ? tr("%1: no answer to the last request, the value is old").arg(m_title) : QString());
    update();
}

void GaugeWidget::setTitle(const QString& title) {
    m_title = title;
    update();
}

void GaugeWidget::setOverloaded(bool overloaded) {
    m_overloaded = overloaded;
    update();
}

QString GaugeWidget::number(double value, int decimals) const {
    return locale().toString(value, 'f', decimals);
}

QString GaugeWidget::valueText() const {
    if (!m_value)
        return QStringLiteral("–");
    return QStringLiteral("%1 %2").arg(number(*m_value, m_decimals), m_unit).trimmed();
}

QSize GaugeWidget::sizeHint() const {
    return {200, 220};
}

QSize GaugeWidget::minimumSizeHint() const {
    return {140, 160};
}

double GaugeWidget::angleOf(double value) const {
    const double fraction = std::clamp((value - m_minimum) / (m_maximum - m_minimum), 0.0, 1.0);
    return StartAngle - Sweep * fraction;
}

void GaugeWidget::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const QFontMetricsF titleMetrics(font());
    const double titleHeight = titleMetrics.height() * 1.6;
    const double side = std::max(40.0, std::min<double>(width(), height() - titleHeight) - 8);
    const QRectF dial((width() - side) / 2, titleHeight + (height() - titleHeight - side) / 2, side, side);
    if (m_overloaded) {
        painter.setPen(QPen(OverloadRed, 2));
        painter.setBrush(Qt::NoBrush);
        painter.drawRoundedRect(QRectF(rect()).adjusted(1, 1, -1, -1), 6, 6);
    }
    paintZones(painter, dial);
    paintScale(painter, dial);
    paintNeedle(painter, dial);
    paintTexts(painter, dial);
}

void GaugeWidget::paintZones(QPainter& painter, const QRectF& dial) const {
    const double band = dial.width() * 0.06;
    const QRectF arc = dial.adjusted(band / 2, band / 2, -band / 2, -band / 2);
    QColor track = palette().color(QPalette::Mid);
    track.setAlpha(90);
    painter.setPen(QPen(track, band, Qt::SolidLine, Qt::FlatCap));
    painter.drawArc(arc, int((StartAngle - Sweep) * 16), int(Sweep * 16));
    double from = m_minimum;
    for (const model::StatusChannel::Zone& zone : m_zones) {
        const double to = std::min(zone.end, m_maximum);
        if (to > from) {
            QColor colour = zoneColour(zone);
            if (m_stale)
                colour.setAlpha(80);
            painter.setPen(QPen(colour, band, Qt::SolidLine, Qt::FlatCap));
            const double a1 = angleOf(from), a2 = angleOf(to);
            painter.drawArc(arc, int(std::round(a2 * 16)), int(std::round((a1 - a2) * 16)));
            from = to;
        }
    }
}

void GaugeWidget::paintScale(QPainter& painter, const QRectF& dial) const {
    const QPointF centre = dial.center();
    const double outer = dial.width() / 2 - dial.width() * 0.07;
    const double step = tickStep(m_maximum - m_minimum);
    const int labelDecimals = decimalsOf(step);
    const QColor ink = palette().color(m_stale ? QPalette::Disabled : QPalette::Active, QPalette::WindowText);
    QFont labelFont = font();
    labelFont.setPointSizeF(std::max(6.0, dial.width() / 22));
    painter.setFont(labelFont);
    const QFontMetricsF metrics(labelFont);
    const double minor =
        step / (std::abs(step / std::pow(10.0, std::floor(std::log10(step))) - 2) < 1e-6 ? 4 : 5);
    const int minorCount = int(std::round((m_maximum - m_minimum) / minor));
    for (int i = 0; i <= minorCount; ++i) {
        const double value = m_minimum + i * minor;
        const double parts = (value - m_minimum) / step;
        const bool major = std::abs(parts - std::round(parts)) < 1e-6;
        const double angle = angleOf(value);
        painter.setPen(QPen(ink, major ? 1.6 : 0.8, Qt::SolidLine, Qt::FlatCap));
        painter.drawLine(onCircle(centre, outer, angle),
                         onCircle(centre, outer * (major ? 0.86 : 0.92), angle));
        if (!major)
            continue;
        const QString label = number(value, labelDecimals);
        const QPointF at = onCircle(centre, outer * 0.86 - metrics.height() * 0.9, angle);
        const QSizeF size(metrics.horizontalAdvance(label), metrics.height());
        painter.drawText(QRectF(at - QPointF(size.width() / 2, size.height() / 2), size), Qt::AlignCenter,
                         label);
    }
}

void GaugeWidget::paintNeedle(QPainter& painter, const QRectF& dial) const {
    if (!m_value)
        return;
    const QPointF centre = dial.center();
    const double length = dial.width() / 2 * 0.74;
    const double angle = angleOf(*m_value);
    QColor colour = m_overloaded ? OverloadRed : palette().color(QPalette::Highlight);
    if (m_stale)
        colour = palette().color(QPalette::Disabled, QPalette::WindowText);
    const double base = dial.width() * 0.025;
    QPainterPath needle;
    needle.moveTo(onCircle(centre, length, angle));
    needle.lineTo(onCircle(centre, base, angle + 90));
    needle.lineTo(onCircle(centre, base * 1.6, angle + 180));
    needle.lineTo(onCircle(centre, base, angle - 90));
    needle.closeSubpath();
    painter.setPen(Qt::NoPen);
    painter.setBrush(colour);
    painter.drawPath(needle);
    painter.setBrush(palette().color(QPalette::WindowText));
    painter.drawEllipse(centre, base * 0.9, base * 0.9);
}

void GaugeWidget::paintTexts(QPainter& painter, const QRectF& dial) const {
    QFont titleFont = font();
    titleFont.setBold(true);
    painter.setFont(titleFont);
    painter.setPen(palette().color(QPalette::WindowText));
    const QRectF titleRect(0, 0, width(), dial.top());
    painter.drawText(titleRect, Qt::AlignCenter,
                     QFontMetrics(titleFont).elidedText(m_title, Qt::ElideRight, width() - 8));

    QFont valueFont = font();
    valueFont.setPointSizeF(std::max(8.0, dial.width() / 12));
    valueFont.setBold(true);
    painter.setFont(valueFont);
    QColor ink = palette().color(QPalette::WindowText);
    if (m_stale)
        ink = palette().color(QPalette::Disabled, QPalette::WindowText);
    else if (m_overloaded)
        ink = OverloadRed;
    painter.setPen(ink);
    const double radius = dial.width() / 2;
    // Between the scale's ends, below the end labels.
    const QRectF valueRect(dial.left(), dial.center().y() + radius * 0.62, dial.width(), radius * 0.38);
    painter.drawText(valueRect, Qt::AlignCenter, valueText());
}

} // namespace stellwerk::ui
