#include "trackplan/TileTag.h"

#include "model/TrackLayout.h"
#include "trackplan/TrackColors.h"

#include <QFontMetrics>
#include <QPainter>
#include <algorithm>
#include <cmath>

namespace stellwerk::ui {
namespace {

using Category = cs2config::TrackCategory;

bool carriesName(Category category) {
    switch (category) {
    case Category::Turnout:
    case Category::Signal:
    case Category::Feedback:
    case Category::RouteButton:
    case Category::Uncoupler:
    case Category::Output:
    case Category::Turntable:
    case Category::TransferTable:
        return true;
    default:
        return false; // track has none; texts and page links draw their own
    }
}

} // namespace

TileTag::TileTag(const model::LayoutTile& tile, const QRect& cell, const QFont& font) : m_font(font) {
    const QString name = tile.text.trimmed();
    if (name.isEmpty() || !carriesName(tile.category) || cell.width() < MinimumTile)
        return;
    const QFontMetrics metrics(m_font);
    // Every name stays on its tile: neighbours (a signal beside its contact, buttons in a row) carry theirs.
    // A route button's goes under the button.
    const bool route = tile.category == Category::RouteButton;
    const int room = cell.width() - 2;
    m_text = name;
    int advance = laidOut(name);
    if (advance + 4 > room) { // shortening lays the text out again: only where it is needed
        m_text = metrics.elidedText(name, Qt::ElideRight, room - 4);
        advance = laidOut(m_text);
    }
    const QSize size(advance + 4, metrics.height());
    const QPoint corner =
        route ? QPoint(cell.center().x() - size.width() / 2, cell.bottom() + 1 - size.height())
              : cell.topLeft() + QPoint(1, 1);
    m_rect = QRect(corner, size);
}

// Shapes the text once; a repaint then only places its glyphs (a third of drawing the text anew).
int TileTag::laidOut(const QString& text) {
    m_glyphs.setText(text);
    m_glyphs.setTextFormat(Qt::PlainText);
    m_glyphs.setPerformanceHint(QStaticText::AggressiveCaching);
    m_glyphs.prepare(QTransform(), m_font);
    return int(std::ceil(m_glyphs.size().width()));
}

QFont TileTag::tagFont(const QFont& font, int tileSize) {
    QFont sized = font;
    sized.setPixelSize(std::clamp(tileSize * 3 / 10, 8, 13));
    return sized;
}

void TileTag::paint(QPainter& painter, const TrackColors& colors) const {
    if (!shown())
        return;
    QColor backing = colors.background;
    backing.setAlpha(215);
    painter.fillRect(m_rect, backing);
    painter.setPen(colors.text);
    painter.drawStaticText(m_rect.topLeft() + QPoint(2, 0), m_glyphs);
}

} // namespace stellwerk::ui
