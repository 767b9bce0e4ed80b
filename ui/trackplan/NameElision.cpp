#include "trackplan/NameElision.h"

#include <QFontMetrics>

namespace stellwerk::ui {

namespace {

const QString Ellipsis = QStringLiteral("…");

bool fits(const QString& text, const QFontMetrics& metrics, int width) {
    return metrics.horizontalAdvance(text) <= width;
}

} // namespace

QString NameElision::shorten(const QString& name, const QFontMetrics& metrics, int width) {
    if (fits(name, metrics, width))
        return name;
    const qsizetype tail = tailLength(name);
    // As much of the start as fits beside the tail; at least the ellipsis and the tail.
    for (qsizetype head = name.size() - tail - 2; head >= 0; --head) {
        const QString text = name.left(head).trimmed() + Ellipsis + name.right(tail);
        if (fits(text, metrics, width))
            return text;
    }
    // Too narrow even for that: the last word alone ("…1"), or as much of the end as fits.
    const QString lastWord = Ellipsis + name.mid(name.lastIndexOf(QLatin1Char(' ')) + 1);
    return fits(lastWord, metrics, width) ? lastWord : metrics.elidedText(name, Qt::ElideLeft, width);
}

qsizetype NameElision::tailLength(const QString& name) {
    const qsizetype space = name.trimmed().lastIndexOf(QLatin1Char(' '));
    if (space > 0)
        return name.size() - space + 1;
    qsizetype digits = 0;
    while (digits < name.size() && name.at(name.size() - 1 - digits).isDigit())
        ++digits;
    return digits < name.size() ? digits : 0;
}

} // namespace stellwerk::ui
