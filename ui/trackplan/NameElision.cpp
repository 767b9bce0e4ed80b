#include "trackplan/NameElision.h"

#include <QFontMetrics>
#include <algorithm>

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
    // Too narrow even for that: the last word alone ("…1"); else a number keeps its end ("…12") and a
    // word both ends of the name ("E…t" and "A…t" for "Einfahrt West" and "Ausfahrt Ost", which end alike).
    const QString word = name.mid(name.lastIndexOf(QLatin1Char(' ')) + 1);
    if (fits(Ellipsis + word, metrics, width))
        return Ellipsis + word;
    const bool number = std::all_of(word.begin(), word.end(), [](QChar c) { return c.isDigit(); });
    const QString ends = name.trimmed().left(1) + Ellipsis + name.trimmed().right(1);
    return !number && fits(ends, metrics, width) ? ends : metrics.elidedText(name, Qt::ElideLeft, width);
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
