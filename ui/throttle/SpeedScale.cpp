#include "throttle/SpeedScale.h"

#include <QEvent>
#include <QPainter>
#include <algorithm>

namespace stellwerk::ui {
namespace {

constexpr int Marks = 5; // about this many labelled marks, 0 included
// The slider's handle keeps this far from its groove's ends; the marks line up with its centre.
constexpr int EndMargin = 10;

} // namespace

SpeedScale::SpeedScale(QWidget* parent) : QWidget(parent) {
    setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Expanding);
}

void SpeedScale::setTachoMax(int kmh) {
    m_tachoMax = std::max(kmh, 0);
    updateGeometry();
    update();
}

int SpeedScale::step() const {
    const int top = m_tachoMax > 0 ? m_tachoMax : 100;
    for (const int candidate : {10, 20, 25, 40, 50, 100, 200})
        if (top / candidate < Marks)
            return candidate;
    return std::max(top / (Marks - 1), 1);
}

QStringList SpeedScale::markTexts() const {
    const int top = m_tachoMax > 0 ? m_tachoMax : 100;
    QStringList texts;
    for (int value = 0; value + step() / 2 < top; value += step())
        texts << QString::number(value);
    texts << (m_tachoMax > 0 ? tr("%1 km/h").arg(top) : tr("%1 %").arg(top));
    return texts;
}

QSize SpeedScale::sizeHint() const {
    const QStringList texts = markTexts();
    int width = 0;
    for (const QString& text : texts)
        width = std::max(width, fontMetrics().horizontalAdvance(text));
    return {width + 10, 160};
}

QSize SpeedScale::minimumSizeHint() const {
    return {sizeHint().width(), 80};
}

void SpeedScale::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setPen(palette().color(QPalette::WindowText));
    const int top = m_tachoMax > 0 ? m_tachoMax : 100;
    const int span = height() - 2 * EndMargin;
    const QStringList texts = markTexts();
    const int textHeight = fontMetrics().height();
    for (qsizetype i = 0; i < texts.size(); ++i) {
        const int value = i + 1 == texts.size() ? top : int(i) * step();
        const int y = height() - EndMargin - span * value / top;
        painter.drawLine(0, y, 4, y);
        painter.drawText(QRect(7, y - textHeight / 2, width() - 7, textHeight),
                         Qt::AlignLeft | Qt::AlignVCenter, texts[i]);
    }
}

void SpeedScale::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) { // "km/h" is translated when painted
        updateGeometry();
        update();
    }
    QWidget::changeEvent(event);
}

} // namespace stellwerk::ui
