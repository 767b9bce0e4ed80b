#pragma once

#include "trackplan/BlockOutlines.h"
#include "trackplan/TileTag.h"
#include "trackplan/TrackColors.h"
#include "trackplan/TrackTileCache.h"
#include "trackplan/TrackTileLook.h"

#include <QWidget>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace stellwerk::model {
struct LayoutPage;
}

namespace stellwerk::ui {

// One page of the track plan on the CS2 grid. It draws the tiles it is given and says which tile was
// clicked; what a tile looks like now and what a click does are the panel's business. It shares the
// ownership of its page, so that it can never draw a page that a replaced railway already freed.
class TrackPageView final : public QWidget {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(TrackPageView)

public:
    // Pixels around the grid.
    static constexpr int Margin = 8;
    using LookOf = std::function<TrackTileLook(int tile)>;
    using TextOf = std::function<QString(int tile)>;

    TrackPageView(std::shared_ptr<const model::LayoutPage> page, LookOf look, TextOf toolTip,
                  QWidget* parent = nullptr);

    int tileSize() const { return m_tileSize; }
    void setTileSize(int pixels);
    // The tile's rectangle in widget coordinates; the tile at a point (null where there is none).
    QRect tileRect(int tile) const;
    std::optional<int> tileAt(QPoint point) const;
    // The name tag a tile carries from its file (TileTag: shown() false when none is drawn).
    TileTag tagOf(int tile) const;
    // Repaints one tile (and the label it may carry beyond its cell).
    void updateTile(int tile);
    QSize sizeHint() const override;
    // The size the page needs at one pixel per tile: columns x rows.
    QSize gridSize() const;
    // The tile's cell at `tileSize` pixels per tile.
    QRect cellAt(int tile, int tileSize) const;
    // The cells (column, row, columns, rows) that hold something drawn; empty for an empty page.
    QRect drawnCells() const;
    // What the page draws at `tileSize` pixels per tile, in the view's pixels: the drawn cells and the
    // texts that run beyond their tiles ("Lokschuppen 1" at the end of its track). Empty for an empty page.
    QRect drawnArea(int tileSize) const;
    // Greyed: the states drawn are the last the station reported, not what it reports now.
    void setDimmed(bool dimmed);
    bool isDimmed() const { return m_dimmed; }
    // The blocks drawn over the page, each with its name (none: an empty BlockOutlines).
    void setBlocks(BlockOutlines blocks);
    // Laid out for the current zoom when the page was last painted.
    const BlockOutlines& blocks() const { return m_blocks; }
    // The tiles marked as having a problem in the drawing (none: empty).
    void setProblemTiles(std::vector<int> tiles);
    const std::vector<int>& problemTiles() const { return m_problemTiles; }
    // Where a tile's problem marker is drawn.
    QRect problemMarkerRect(int tile) const;
    // Takes locomotives dragged onto its tiles (LocomotiveMime), while trains can be placed.
    void setLocomotiveDrops(bool accepted) { setAcceptDrops(accepted); }

signals:
    void tileClicked(int tile);
    void tileMenuRequested(int tile, QPoint globalPosition);
    // Ctrl + wheel: positive steps zoom in.
    void zoomRequested(int steps);
    // A locomotive was dropped on a tile, at `point` (the view's pixels).
    void locomotiveDropped(quint32 locId, int tile, QPoint point);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    bool event(QEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dragMoveEvent(QDragMoveEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void paintGrid(QPainter& painter, const QRect& area) const;
    std::vector<TrackTileCache::Placed> picturesIn(const QRect& area);
    // The tags a paint draws: names from the file, and locomotives, which run over their neighbours and
    // are drawn last.
    struct TagsInArea {
        TileTagBatch names;
        std::vector<TileTag> occupants;
    };
    TagsInArea tagsIn(const QRect& area);
    QFont tagFont() const;
    void layOutBlocks();
    void paintProblemMarkers(QPainter& painter, const QRect& area) const;

    std::shared_ptr<const model::LayoutPage> m_pageOwner;
    const model::LayoutPage& m_page;
    LookOf m_look;
    TextOf m_toolTip;
    TrackColors m_colors;
    TrackTileCache m_pictures;
    TileTagCache m_tags;
    mutable QFont m_tagFont; // the tags' font for m_tagFontTile and m_tagFontBase
    mutable QFont m_tagFontBase;
    mutable int m_tagFontTile = 0;
    mutable std::optional<QRect> m_drawnArea; // drawnArea(m_tileSize), asked for by every layout pass
    BlockOutlines m_blocks;
    std::vector<int> m_problemTiles;
    int m_tileSize = 40;
    bool m_dimmed = false;
};

} // namespace stellwerk::ui
