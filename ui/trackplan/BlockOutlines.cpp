#include "trackplan/BlockOutlines.h"

#include "trackplan/PlanGraph.h"
#include "trackplan/TrackColors.h"

#include <QFontMetrics>
#include <QPainter>
#include <QRegion>
#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_map>
#include <utility>

namespace stellwerk::ui {
namespace {

using Cells = std::set<std::pair<int, int>>;

bool has(const Cells& cells, int column, int row) {
    return cells.contains({column, row});
}

// The cells of a block's track on one page in the order of its path (else its cells), from the middle
// outwards: where its name reads best.
std::vector<QPoint> fromTheMiddle(const std::vector<QPoint>& cells) {
    const int count = int(cells.size());
    const int middle = count / 2;
    std::vector<QPoint> ordered;
    if (count > 0)
        ordered.push_back(cells[std::size_t(middle)]);
    for (int step = 1; step <= middle + 1; ++step) {
        if (middle - step >= 0)
            ordered.push_back(cells[std::size_t(middle - step)]);
        if (middle + step < count)
            ordered.push_back(cells[std::size_t(middle + step)]);
    }
    return ordered;
}

constexpr int NamePaddingX = 4;
constexpr int NamePaddingY = 1;

} // namespace

// What the page draws, found by the cells it covers, so that a name's place is checked against the few
// things near it rather than every tile of the page.
class BlockOutlines::TakenAreas {
public:
    explicit TakenAreas(int cellSize) : m_cellSize(std::max(1, cellSize)) {}

    void add(const QRect& rect) {
        m_rects.push_back(rect);
        forCells(rect, [&](std::uint64_t cell) { m_cells[cell].push_back(m_rects.size() - 1); });
    }
    bool covers(const QRect& rect) const {
        bool covered = false;
        forCells(rect, [&](std::uint64_t cell) {
            if (const auto found = m_cells.find(cell); found != m_cells.end())
                for (const std::size_t index : found->second)
                    covered = covered || m_rects[index].intersects(rect);
        });
        return covered;
    }

private:
    template <class Visit>
    void forCells(const QRect& rect, Visit visit) const {
        const auto cellOf = [this](int pixel) {
            return std::int64_t(std::floor(double(pixel) / m_cellSize));
        };
        for (std::int64_t row = cellOf(rect.top()); row <= cellOf(rect.bottom()); ++row)
            for (std::int64_t column = cellOf(rect.left()); column <= cellOf(rect.right()); ++column)
                visit(std::uint64_t(row + (1 << 20)) << 32 | std::uint32_t(column + (1 << 20)));
    }

    int m_cellSize;
    std::vector<QRect> m_rects;
    std::unordered_map<std::uint64_t, std::vector<std::size_t>> m_cells;
};

BlockOutlines::BlockOutlines(std::vector<Block> blocks) : m_blocks(std::move(blocks)) {}

BlockOutlines BlockOutlines::ofPage(const PlanGraph& graph, int page, const StateOf& stateOf) {
    return ofPage(graph, page,
                  [&stateOf](int block) {
                      return Mark{BlockShade::Plain, stateOf ? stateOf(block) : QString()};
                  },
                  true, {});
}

BlockOutlines BlockOutlines::ofPage(const PlanGraph& graph, int page, const MarkOf& markOf, bool allBlocks,
                                    const std::vector<int>& ways) {
    std::vector<Block> parts;
    const trackgraph::TrackGraph& g = graph.graph();
    const auto onPage = [&](trackgraph::TileId id) {
        const std::optional<model::TileRef> at = graph.planTile(id);
        return at && at->page == page;
    };
    const auto cellOf = [&](trackgraph::TileId id) {
        const trackgraph::TilePlace& place = g.tile(id).place;
        return QPoint(place.column, place.row);
    };
    for (const trackgraph::Block& block : g.blocks()) {
        const Mark mark = markOf(block.id);
        if (!allBlocks && (mark.shade == BlockShade::Plain || mark.shade == BlockShade::Free))
            continue;
        Block part{block.id, QString::fromStdString(block.name), {}, {}, mark.shade};
        if (!mark.words.isEmpty())
            part.name += QStringLiteral(" · ") + mark.words;
        for (const trackgraph::TileId id : block.tiles)
            if (onPage(id))
                part.cells.push_back(cellOf(id));
        if (part.cells.empty())
            continue;
        std::vector<QPoint> along;
        for (const trackgraph::TrackStep& step : block.path)
            if (onPage(step.tile))
                along.push_back(cellOf(step.tile));
        part.nameCells = fromTheMiddle(along.empty() ? part.cells : along);
        parts.push_back(std::move(part));
    }
    for (const int id : ways) {
        const trackgraph::Connection& connection = g.connection(id);
        std::set<std::pair<int, int>> seen;
        Block way{-id, QString(), {}, {}, BlockShade::Reserved};
        const auto add = [&](trackgraph::TileId tile) {
            const QPoint cell = cellOf(tile);
            if (onPage(tile) && seen.insert({cell.x(), cell.y()}).second)
                way.cells.push_back(cell);
        };
        for (const trackgraph::TrackStep& step : connection.path)
            add(step.tile);
        for (const trackgraph::TurnoutOnWay& turnout : connection.turnouts)
            add(turnout.tile);
        for (const trackgraph::TileId crossing : connection.crossings)
            add(crossing);
        if (!way.cells.empty())
            parts.push_back(std::move(way));
    }
    return BlockOutlines(std::move(parts));
}

bool BlockOutlines::needsLayout(int tileSize, const QFont& font, qreal pixelRatio) const {
    return m_drawn.size() != m_blocks.size() || m_layout.tileSize != tileSize || m_layout.font != font ||
           m_layout.pixelRatio != pixelRatio;
}

void BlockOutlines::layOut(const Layout& layout, const std::vector<QRect>& taken, const TrackColors& colors) {
    m_layout = layout;
    m_drawn.clear();
    m_drawn.reserve(m_blocks.size());
    TakenAreas covered(layout.tileSize);
    for (const QRect& rect : taken)
        covered.add(rect);
    for (const Block& block : m_blocks) {
        Drawn drawn = band(block);
        drawn.look = BlockShadeLook::of(block.shade, colors);
        if (m_layout.tileSize >= NamesFromTile && !block.name.isEmpty()) {
            drawn.name = placeName(block, covered);
            drawn.tab = tabPicture(block.name, drawn.name.size(), drawn.look);
            covered.add(drawn.name);
        }
        m_drawn.push_back(std::move(drawn));
    }
}

int BlockOutlines::inset() const {
    return std::max(2, m_layout.tileSize / 10);
}

QRect BlockOutlines::cellRect(QPoint cell) const {
    const int size = m_layout.tileSize;
    return {m_layout.origin.x() + cell.x() * size, m_layout.origin.y() + cell.y() * size, size, size};
}

// The block's cells drawn in from the sides where the block ends (so that two blocks side by side show
// where one ends), without the corners that would poke out where its track turns.
BlockOutlines::Drawn BlockOutlines::band(const Block& block) const {
    Cells cells;
    for (const QPoint& cell : block.cells)
        cells.insert({cell.x(), cell.y()});
    const int in = inset();
    QRegion region;
    for (const QPoint& cell : block.cells) {
        const int c = cell.x(), r = cell.y();
        region += cellRect(cell).adjusted(has(cells, c - 1, r) ? 0 : in, has(cells, c, r - 1) ? 0 : in,
                                          has(cells, c + 1, r) ? 0 : -in, has(cells, c, r + 1) ? 0 : -in);
    }
    for (const QPoint& cell : block.cells)
        for (const int dx : {-1, 1})
            for (const int dy : {-1, 1}) {
                const int c = cell.x(), r = cell.y();
                if (!has(cells, c + dx, r) || !has(cells, c, r + dy) || has(cells, c + dx, r + dy))
                    continue;
                const QRect rect = cellRect(cell);
                region -= QRect(dx < 0 ? rect.left() : rect.right() - in + 1,
                                dy < 0 ? rect.top() : rect.bottom() - in + 1, in, in);
            }
    // The edge: what is left of the band when it is shrunk by its width from every side.
    constexpr int EdgeWidth = 2;
    QRegion inner = region;
    for (const QPoint& step :
         {QPoint(EdgeWidth, 0), QPoint(-EdgeWidth, 0), QPoint(0, EdgeWidth), QPoint(0, -EdgeWidth)})
        inner &= region.translated(step);
    Drawn drawn;
    drawn.fill.assign(inner.begin(), inner.end());
    const QRegion edge = region - inner;
    drawn.edge.assign(edge.begin(), edge.end());
    drawn.bounds = region.boundingRect();
    return drawn;
}

// A tab just below (else above) a cell of the block's track, from the middle outwards, where it covers
// nothing drawn; else inside the block's middle cell, at its foot.
QRect BlockOutlines::placeName(const Block& block, const TakenAreas& taken) const {
    const QFontMetrics metrics(m_layout.font);
    const QSize size(metrics.horizontalAdvance(block.name) + 2 * NamePaddingX,
                     metrics.height() + 2 * NamePaddingY);
    const auto free = [&](const QRect& tab) { return m_layout.room.contains(tab) && !taken.covers(tab); };
    for (const QPoint& cell : block.nameCells) {
        const QRect rect = cellRect(cell);
        const int left = rect.center().x() - size.width() / 2;
        if (const QRect below(QPoint(left, rect.bottom() + 2), size); free(below))
            return below;
        if (const QRect above(QPoint(left, rect.top() - 1 - size.height()), size); free(above))
            return above;
    }
    const QRect middle = cellRect(block.nameCells.empty() ? block.cells.front() : block.nameCells.front());
    QRect inside(QPoint(middle.center().x() - size.width() / 2, middle.bottom() - inset() - size.height()),
                 size);
    // Kept on the page: a block at its edge would have its name cut off there.
    if (inside.right() > m_layout.room.right())
        inside.moveRight(m_layout.room.right());
    if (inside.left() < m_layout.room.left())
        inside.moveLeft(m_layout.room.left());
    return inside;
}

// The name in the tab's text colour on a rounded tab of the block's colour, drawn once per zoom.
QImage BlockOutlines::tabPicture(const QString& name, QSize size, const BlockShadeLook& look) const {
    QImage tab(size * m_layout.pixelRatio, QImage::Format_ARGB32_Premultiplied);
    tab.setDevicePixelRatio(m_layout.pixelRatio);
    tab.fill(Qt::transparent);
    QPainter painter(&tab);
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(Qt::NoPen);
    painter.setBrush(look.edge);
    painter.drawRoundedRect(QRectF(QPointF(0, 0), QSizeF(size)), 3, 3);
    painter.setFont(m_layout.font);
    painter.setPen(look.text);
    painter.drawText(QRect(QPoint(0, 0), size), Qt::AlignCenter, name);
    return tab;
}

void BlockOutlines::paintBands(QPainter& painter, const QRect& area, const TrackColors& /*colors*/) const {
    painter.save();
    painter.setBrushOrigin(m_layout.origin); // the patterns line up across the bands painted on other cores
    for (const Drawn& drawn : m_drawn) {
        if (!drawn.bounds.intersects(area))
            continue;
        for (const QRect& rect : drawn.fill)
            painter.fillRect(rect, drawn.look.band);
        for (const QRect& rect : drawn.edge)
            painter.fillRect(rect, drawn.look.edge);
    }
    painter.restore();
}

void BlockOutlines::paintNames(QPainter& painter, const QRect& area) const {
    for (const Drawn& drawn : m_drawn)
        if (!drawn.name.isEmpty() && drawn.name.intersects(area))
            painter.drawImage(drawn.name.topLeft(), drawn.tab);
}

QRect BlockOutlines::bandRect(int block) const {
    for (std::size_t i = 0; i < m_drawn.size(); ++i)
        if (m_blocks[i].id == block)
            return m_drawn[i].bounds;
    return {};
}

QRect BlockOutlines::nameRect(int block) const {
    for (std::size_t i = 0; i < m_drawn.size(); ++i)
        if (m_blocks[i].id == block)
            return m_drawn[i].name;
    return {};
}

} // namespace stellwerk::ui
