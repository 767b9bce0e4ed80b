#include "trackplan/TrackPageView.h"

#include "common/LocomotiveMime.h"
#include "model/TrackLayout.h"
#include "trackplan/PaintBands.h"
#include "trackplan/TileTag.h"
#include "trackplan/TrackTilePainter.h"

#include <QContextMenuEvent>
#include <QDragEnterEvent>
#include <QDragMoveEvent>
#include <QDropEvent>
#include <QElapsedTimer>
#include <QHelpEvent>
#include <QMimeData>
#include <QPaintEvent>
#include <QPainter>
#include <QToolTip>
#include <algorithm>
#include <cstdio>

namespace stellwerk::ui {
namespace {

constexpr int MinimumColumns = 20; // the CS2's page is at least 20 x 15 tiles
constexpr int MinimumRows = 15;

} // namespace

TrackPageView::TrackPageView(std::shared_ptr<const model::LayoutPage> page, LookOf look, TextOf toolTip,
                             QWidget* parent)
    : QWidget(parent), m_pageOwner(std::move(page)), m_page(*m_pageOwner), m_look(std::move(look)),
      m_toolTip(std::move(toolTip)), m_colors(TrackColors::from(palette())) {
    setObjectName(QStringLiteral("trackPageView"));
    setMouseTracking(false);
    setAttribute(Qt::WA_OpaquePaintEvent);
}

void TrackPageView::setTileSize(int pixels) {
    if (pixels == m_tileSize)
        return;
    m_tileSize = pixels;
    m_tags.clear();
    m_drawnArea.reset();
    updateGeometry();
    resize(sizeHint());
    update();
}

void TrackPageView::setBlocks(BlockOutlines blocks) {
    m_blocks = std::move(blocks);
    update();
}

void TrackPageView::setProblemTiles(std::vector<int> tiles) {
    m_problemTiles = std::move(tiles);
    update();
}

void TrackPageView::setDimmed(bool dimmed) {
    if (dimmed == m_dimmed)
        return;
    m_dimmed = dimmed;
    update();
}

QSize TrackPageView::gridSize() const {
    return {std::max(m_page.columns, MinimumColumns), std::max(m_page.rows, MinimumRows)};
}

QRect TrackPageView::drawnCells() const {
    QRect drawn;
    for (const model::LayoutTile& tile : m_page.tiles)
        if (tile.type != QLatin1String("leer"))
            drawn |= QRect(tile.position.column, tile.position.row, 1, 1);
    return drawn;
}

QRect TrackPageView::drawnArea(int tileSize) const {
    QRect drawn;
    for (int i = 0; i < int(m_page.tiles.size()); ++i) {
        const model::LayoutTile& tile = m_page.tiles[std::size_t(i)];
        if (tile.type == QLatin1String("leer"))
            continue;
        const QRect cell = cellAt(i, tileSize);
        drawn |= tile.category == cs2config::TrackCategory::Text
                     ? cell | TrackTilePainter::area(cell, m_look(i), font()).toAlignedRect()
                     : cell;
    }
    return drawn;
}

// The grid, and beyond it any text that runs over its edge, so that scrolling reaches all of it.
QSize TrackPageView::sizeHint() const {
    const QSize grid = gridSize() * m_tileSize + QSize(2 * Margin, 2 * Margin);
    if (!m_drawnArea)
        m_drawnArea = drawnArea(m_tileSize);
    const QRect drawn = *m_drawnArea;
    return drawn.isEmpty() ? grid
                           : grid.expandedTo(QSize(drawn.right() + 1 + Margin, drawn.bottom() + 1 + Margin));
}

QRect TrackPageView::tileRect(int tile) const {
    return cellAt(tile, m_tileSize);
}

QRect TrackPageView::cellAt(int tile, int tileSize) const {
    const model::LayoutTile& t = m_page.tiles[std::size_t(tile)];
    return {Margin + t.position.column * tileSize, Margin + t.position.row * tileSize, tileSize, tileSize};
}

std::optional<int> TrackPageView::tileAt(QPoint point) const {
    for (int i = int(m_page.tiles.size()) - 1; i >= 0; --i)
        if (tileRect(i).contains(point) && m_page.tiles[std::size_t(i)].type != QLatin1String("leer"))
            return i;
    return std::nullopt;
}

void TrackPageView::updateTile(int tile) {
    const QRect cell = tileRect(tile);
    const auto category = m_page.tiles[std::size_t(tile)].category;
    if (category == cs2config::TrackCategory::Text)
        update(QRect(0, cell.top(), width(), cell.height()).united(cell.adjusted(0, -width(), 0, width())));
    else if (category == cs2config::TrackCategory::Feedback)
        update(TileTag::occupantReach(cell)); // the name of the locomotive on it runs further
    else
        update(cell);
}

void TrackPageView::paintGrid(QPainter& painter, const QRect& area) const {
    painter.fillRect(area, m_colors.background);
    painter.setPen(QPen(m_colors.grid, 1));
    const QSize grid = gridSize();
    for (int x = 0; x <= grid.width(); ++x)
        painter.drawLine(Margin + x * m_tileSize, Margin, Margin + x * m_tileSize,
                         Margin + grid.height() * m_tileSize);
    for (int y = 0; y <= grid.height(); ++y)
        painter.drawLine(Margin, Margin + y * m_tileSize, Margin + grid.width() * m_tileSize,
                         Margin + y * m_tileSize);
}

void TrackPageView::paintEvent(QPaintEvent* event) {
    QPainter painter(this);
    const QRect area = event->rect();
    painter.setClipRect(area);
    const std::vector<TrackTileCache::Placed> pictures = picturesIn(area);
    const TagsInArea tags = tagsIn(area);
    layOutBlocks();
    // The grid, the blocks' bands, the tiles and the names on all cores; names that Qt laid out, occupants,
    // the blocks' names and the problem markers on this thread.
    PaintBands::paint(painter, area, [this, &pictures, &tags](QPainter& band, const QRect& part) {
        paintGrid(band, part);
        m_blocks.paintBands(band, part, m_colors);
        for (const TrackTileCache::Placed& picture : pictures)
            if (picture.area().intersects(part))
                picture.paint(band);
        tags.names.paintBackings(band, m_colors, part);
        tags.names.paintGlyphs(band, m_colors);
        m_blocks.paintNames(band, part);
    });
    tags.names.paintShaped(painter, m_colors);
    for (const TileTag& occupant : tags.occupants)
        occupant.paint(painter, m_colors);
    paintProblemMarkers(painter, area);
    if (m_dimmed) { // a wash of the background over every state: "not reported", at a glance
        QColor wash = m_colors.background;
        wash.setAlpha(150);
        painter.fillRect(area, wash);
    }
}

// The blocks' bands and names for this zoom, where the names cover nothing the page draws if they can.
void TrackPageView::layOutBlocks() {
    QFont nameFont = tagFont();
    nameFont.setBold(true);
    if (m_blocks.isEmpty() || !m_blocks.needsLayout(m_tileSize, nameFont, devicePixelRatioF()))
        return;
    std::vector<QRect> taken;
    for (int i = 0; i < int(m_page.tiles.size()); ++i) {
        const model::LayoutTile& tile = m_page.tiles[std::size_t(i)];
        if (tile.type == QLatin1String("leer"))
            continue;
        const QRect cell = tileRect(i);
        taken.push_back(tile.category == cs2config::TrackCategory::Text
                            ? TrackTilePainter::area(cell, m_look(i), font()).toAlignedRect()
                            : cell);
    }
    const QRect room(Margin, Margin, gridSize().width() * m_tileSize, gridSize().height() * m_tileSize);
    m_blocks.layOut({m_tileSize, QPoint(Margin, Margin), nameFont, room, devicePixelRatioF()}, taken,
                    m_colors);
}

QRect TrackPageView::problemMarkerRect(int tile) const {
    const QRect cell = tileRect(tile);
    const int size = std::clamp(m_tileSize * 2 / 5, 9, 18);
    return {cell.right() - size, cell.top() + 1, size, size};
}

// An amber disc with "!" at the top right of each tile with a problem (the tile's name is at its top left).
void TrackPageView::paintProblemMarkers(QPainter& painter, const QRect& area) const {
    if (m_problemTiles.empty())
        return;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    QFont font = painter.font();
    font.setBold(true);
    for (const int tile : m_problemTiles) {
        const QRect marker = problemMarkerRect(tile);
        if (!marker.intersects(area))
            continue;
        font.setPixelSize(std::max(7, marker.height() - 4));
        painter.setFont(font);
        painter.setPen(QPen(QColor(122, 82, 0), 1));
        painter.setBrush(m_colors.problem);
        painter.drawEllipse(QRectF(marker).adjusted(0.5, 0.5, -0.5, -0.5));
        painter.setPen(Qt::black);
        painter.drawText(marker, Qt::AlignCenter, QStringLiteral("!"));
    }
    painter.restore();
}

// The pictures of the tiles that reach into the area, in the page's order; those not drawn yet are drawn
// first, all at once.
std::vector<TrackTileCache::Placed> TrackPageView::picturesIn(const QRect& area) {
    m_pictures.prepare(m_tileSize, devicePixelRatioF(), m_colors, font());
    std::vector<int> tiles;
    std::vector<TrackTileLook> looks;
    for (int i = 0; i < int(m_page.tiles.size()); ++i) {
        const bool label = m_page.tiles[std::size_t(i)].category == cs2config::TrackCategory::Text;
        constexpr int reach = TrackTileCache::Overhang;
        if (label || tileRect(i).adjusted(-reach, -reach, reach, reach).intersects(area)) {
            tiles.push_back(i);
            looks.push_back(m_look(i));
        }
    }
    m_pictures.drawAhead(looks);
    std::vector<TrackTileCache::Placed> pictures;
    pictures.reserve(tiles.size());
    for (std::size_t k = 0; k < tiles.size(); ++k) {
        TrackTileCache::Placed picture = m_pictures.placed(looks[k], tileRect(tiles[k]).topLeft());
        if (!picture.image.isNull() && picture.area().intersects(area)) // labels may reach in from elsewhere
            pictures.push_back(std::move(picture));
    }
    return pictures;
}

// The names from the file that reach into the area, and the locomotives on occupied contacts there.
TrackPageView::TagsInArea TrackPageView::tagsIn(const QRect& area) {
    const QFont font = tagFont();
    TagsInArea tags{TileTagBatch(font), {}};
    if (m_tileSize < TileTag::MinimumTile)
        return tags;
    const int tiles = int(m_page.tiles.size());
    for (int i = 0; i < tiles; ++i) {
        const QRect cell = tileRect(i);
        if (m_page.tiles[std::size_t(i)].category == cs2config::TrackCategory::Feedback &&
            TileTag::occupantReach(cell).intersects(area))
            if (const QString occupant = m_look(i).occupant; !occupant.isEmpty()) {
                tags.occupants.push_back(TileTag::occupant(occupant, cell, font));
                continue;
            }
        if (cell.intersects(area)) // a name stays on its tile
            tags.names.add(
                m_tags.tag(i, tiles, [&] { return TileTag(m_page.tiles[std::size_t(i)], cell, font); }));
    }
    return tags;
}

QFont TrackPageView::tagFont() const {
    if (m_tagFontTile != m_tileSize || m_tagFontBase != font()) {
        m_tagFontTile = m_tileSize;
        m_tagFontBase = font();
        m_tagFont = TileTag::tagFont(font(), m_tileSize); // one font shared by every tag
    }
    return m_tagFont;
}

TileTag TrackPageView::tagOf(int tile) const {
    return TileTag(m_page.tiles[std::size_t(tile)], tileRect(tile), tagFont());
}

void TrackPageView::mouseReleaseEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton)
        if (const std::optional<int> tile = tileAt(event->position().toPoint()))
            emit tileClicked(*tile);
    QWidget::mouseReleaseEvent(event);
}

void TrackPageView::contextMenuEvent(QContextMenuEvent* event) {
    if (const std::optional<int> tile = tileAt(event->pos()))
        emit tileMenuRequested(*tile, event->globalPos());
}

void TrackPageView::wheelEvent(QWheelEvent* event) {
    if (!(event->modifiers() & Qt::ControlModifier)) {
        QWidget::wheelEvent(event);
        return;
    }
    const int steps = event->angleDelta().y() / 120;
    if (steps != 0)
        emit zoomRequested(steps);
    event->accept();
}

bool TrackPageView::event(QEvent* event) {
    if (event->type() == QEvent::ToolTip) {
        auto* help = static_cast<QHelpEvent*>(event);
        const std::optional<int> tile = tileAt(help->pos());
        if (tile)
            QToolTip::showText(help->globalPos(), m_toolTip(*tile), this, tileRect(*tile));
        else
            QToolTip::hideText();
        return true;
    }
    if (event->type() == QEvent::PaletteChange) {
        m_colors = TrackColors::from(palette());
        m_blocks.forgetLayout();
        update();
    }
    if (event->type() == QEvent::FontChange || event->type() == QEvent::ScreenChangeInternal) {
        m_tags.clear();
        m_drawnArea.reset();
    }
    return QWidget::event(event);
}

void TrackPageView::dragEnterEvent(QDragEnterEvent* event) {
    if (LocomotiveMime::locId(event->mimeData()))
        event->acceptProposedAction();
}

// Only a tile takes the locomotive (the panel says whether it lies in a block).
void TrackPageView::dragMoveEvent(QDragMoveEvent* event) {
    if (LocomotiveMime::locId(event->mimeData()) && tileAt(event->position().toPoint()))
        event->acceptProposedAction();
    else
        event->ignore();
}

void TrackPageView::dropEvent(QDropEvent* event) {
    const std::optional<std::uint32_t> locId = LocomotiveMime::locId(event->mimeData());
    const QPoint point = event->position().toPoint();
    const std::optional<int> tile = tileAt(point);
    if (!locId || !tile) {
        event->ignore();
        return;
    }
    event->acceptProposedAction();
    emit locomotiveDropped(*locId, *tile, point);
}

} // namespace stellwerk::ui
