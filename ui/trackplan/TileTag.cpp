#include "trackplan/TileTag.h"

#include "model/TrackLayout.h"
#include "trackplan/TrackColors.h"

#include <QFontMetrics>
#include <QPainter>
#include <algorithm>

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
    m_font.setPixelSize(std::clamp(cell.width() * 3 / 10, 8, 13));
    const QFontMetrics metrics(m_font);
    // Every name stays on its tile: neighbours (a signal beside its contact, buttons in a row) carry theirs.
    // A route button's goes under the button.
    const bool route = tile.category == Category::RouteButton;
    const int room = cell.width() - 2;
    m_text = metrics.elidedText(name, Qt::ElideRight, room);
    const QSize size(metrics.horizontalAdvance(m_text) + 4, metrics.height());
    const QPoint corner =
        route ? QPoint(cell.center().x() - size.width() / 2, cell.bottom() + 1 - size.height())
              : cell.topLeft() + QPoint(1, 1);
    m_rect = QRect(corner, size);
}

QPixmap TileTag::picture(const TrackColors& colors, double devicePixelRatio) const {
    if (!shown())
        return {};
    QPixmap pixmap(m_rect.size() * devicePixelRatio);
    pixmap.setDevicePixelRatio(devicePixelRatio);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.translate(-m_rect.topLeft());
    paint(painter, colors);
    return pixmap;
}

void TileTag::paint(QPainter& painter, const TrackColors& colors) const {
    if (!shown())
        return;
    QColor backing = colors.background;
    backing.setAlpha(215);
    painter.setPen(Qt::NoPen);
    painter.setBrush(backing);
    painter.drawRoundedRect(m_rect, 2, 2);
    painter.setFont(m_font);
    painter.setPen(colors.text);
    painter.drawText(m_rect, Qt::AlignCenter, m_text);
}

} // namespace stellwerk::ui
