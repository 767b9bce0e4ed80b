#pragma once

#include "trackplan/BlockShades.h"

#include <QFont>
#include <QImage>
#include <QPoint>
#include <QRect>
#include <QString>
#include <functional>
#include <vector>

class QPainter;

namespace stellwerk::ui {

class PlanGraph;
struct TrackColors;

// The blocks of one page of the plan drawn as translucent bands over their tiles, each with its name on a
// tab beside it, shaded as the automation says (BlockShade), and the connections of reserved ways as bands
// without a name. Which cells a block covers comes from the track graph once per layout; the bands, their
// edges, the places of the names and the tabs' pictures are made once per zoom, so that a repaint only
// fills rectangles and blits pictures it knows (on any thread).
class BlockOutlines final {
public:
    // One block's part of the page: its cells (column, row), and the cells its name may be placed next
    // to, best first (from the middle of its track outwards).
    struct Block {
        int id = 0;
        QString name;
        std::vector<QPoint> cells;
        std::vector<QPoint> nameCells;
        BlockShade shade = BlockShade::Plain;
    };

    BlockOutlines() = default;
    explicit BlockOutlines(std::vector<Block> blocks);
    // What is said of a block beside its name (a state another program announced); empty for nothing.
    using StateOf = std::function<QString(int block)>;
    // The parts of the graph's blocks on one page of the plan (index into the layout's pages), each named
    // "name · state" where `stateOf` says something.
    static BlockOutlines ofPage(const PlanGraph& graph, int page, const StateOf& stateOf = {});
    // What the automation says of a block: its shade and the words beside its name.
    struct Mark {
        BlockShade shade = BlockShade::Plain;
        QString words;
    };
    using MarkOf = std::function<Mark(int block)>;
    // The blocks marked by `markOf` (only those shaded other than free when `allBlocks` is false), and the
    // reserved connections `ways` (graph connection ids) as unnamed bands in the reserved shade; a way's id
    // is the connection's, negated.
    static BlockOutlines ofPage(const PlanGraph& graph, int page, const MarkOf& markOf, bool allBlocks,
                                const std::vector<int>& ways);

    bool isEmpty() const { return m_blocks.empty(); }
    const std::vector<Block>& blocks() const { return m_blocks; }

    // True when layOut() must run for this zoom, font and screen.
    bool needsLayout(int tileSize, const QFont& font, qreal pixelRatio) const;
    // Needs a layout again (the palette changed: the tabs are drawn in its colours).
    void forgetLayout() { m_drawn.clear(); }
    // Where the bands go: cells of `tileSize` pixels on a grid that starts at `origin`; names in `font`
    // inside `room` (the page's pixels), where they cover none of `taken` (what the page draws) if they can.
    struct Layout {
        int tileSize = 0;
        QPoint origin;
        QFont font;
        QRect room;
        qreal pixelRatio = 1; // the screen's, for sharp tabs
    };
    // Names are drawn from this tile size on (smaller, they would cover the plan).
    static constexpr int NamesFromTile = 16;
    void layOut(const Layout& layout, const std::vector<QRect>& taken, const TrackColors& colors);

    // The bands and their edges in `area`, under the tiles; may be called on any thread (reads only what
    // layOut made).
    void paintBands(QPainter& painter, const QRect& area, const TrackColors& colors) const;
    // The names' tabs in `area`, over the tiles; on any thread too.
    void paintNames(QPainter& painter, const QRect& area) const;

    // Where a block's band and name are drawn at the last layout (empty when the page has none of it).
    QRect bandRect(int block) const;
    QRect nameRect(int block) const;

private:
    struct Drawn {
        std::vector<QRect> fill; // translucent
        std::vector<QRect> edge; // solid, inside the band's border
        QRect bounds;
        QRect name;
        QImage tab; // the name on its tab
        BlockShadeLook look;
    };
    Drawn band(const Block& block) const;
    class TakenAreas;
    QRect placeName(const Block& block, const TakenAreas& taken) const;
    QImage tabPicture(const QString& name, QSize size, const BlockShadeLook& look) const;
    QRect cellRect(QPoint cell) const;
    int inset() const;

    std::vector<Block> m_blocks;
    std::vector<Drawn> m_drawn; // per block, for m_layout
    Layout m_layout;
};

} // namespace stellwerk::ui
