#pragma once

#include <QColor>
#include <QFont>
#include <QGlyphRun>
#include <QRect>
#include <QStaticText>
#include <QString>
#include <optional>
#include <vector>

class QPainter;

namespace stellwerk::model {
struct LayoutTile;
}

namespace stellwerk::ui {

struct TrackColors;

// The name an element carries in its file (`.text`: a turnout's number, a signal's name, an S88 contact's
// number, a route's name), drawn small on a light backing at the tile's top left (under a route button)
// and shortened to the tile keeping the end that tells neighbours apart (NameElision), so that the plan
// reads like the station's own. Too small a zoom draws none.
class TileTag final {
public:
    // Tiles smaller than this carry no tag: the text would not be readable.
    static constexpr int MinimumTile = 26;
    // The smallest text a tag is drawn in, in pixels: readable on a laptop's screen.
    static constexpr int ReadablePixels = 9;

    // `font` is the plan's font; every tag of one zoom shares the font sized from it (tagFont).
    TileTag(const model::LayoutTile& tile, const QRect& cell, const QFont& font);
    // The name of the locomotive on an occupied contact, in the occupied colour at the tile's top left; it
    // may run over OccupantTiles tiles, since a locomotive's name is longer than a contact's number.
    static TileTag occupant(const QString& name, const QRect& cell, const QFont& font);
    static constexpr int OccupantTiles = 3;
    // The area an occupant's tag may cover, for repainting the contact's tile.
    static QRect occupantReach(const QRect& cell);
    // The font of the tags on tiles of `tileSize` pixels.
    static QFont tagFont(const QFont& font, int tileSize);

    bool shown() const { return !m_text.isEmpty(); }
    // Where the tag is drawn, inside the tile; empty when none is shown.
    QRect rect() const { return m_rect; }
    QString text() const { return m_text; }
    bool isOccupant() const { return m_occupant; }
    QFont font() const { return m_font; }
    // Draws the tag; the painter's font must be font() (the tags of a page share it: setting it once
    // for all saves a font lookup per tag).
    void paint(QPainter& painter, const TrackColors& colors) const;
    // paint() in two steps: the backing (on any thread), then the text (on the GUI thread, which owns
    // the font's glyphs).
    void paintBacking(QPainter& painter, const TrackColors& colors) const;
    void paintText(QPainter& painter, const TrackColors& colors) const;

private:
    friend class TileTagBatch;
    QColor textColor(const TrackColors& colors) const;
    explicit TileTag(const QFont& font) : m_font(font) {}
    int laidOut(const QString& text);
    int laidOutByQt(const QString& text);
    void place(const QString& name, QPoint corner, int room);

    QFont m_font;
    QString m_text;
    QRect m_rect;
    bool m_occupant = false;
    QGlyphRun m_glyphs; // m_text's glyphs placed in m_font, from the rect's top left
    // m_text laid out by Qt, when m_font lacks one of its characters (made only then: 2,000 tags would
    // otherwise touch a megabyte of new memory for nothing)
    std::optional<QStaticText> m_shaped;
};

// The names of a page painted in two calls instead of two per tag: every backing, then every glyph in one
// run; both may be painted on any thread (the paint bands do them on all cores). Names stay inside their
// tiles, so none covers another's and the order does not change the picture. A name with a character the
// tags' font lacks is laid out by Qt and drawn on the GUI thread (paintShaped). Occupants run over their
// neighbours and are drawn on their own, after.
class TileTagBatch final {
public:
    explicit TileTagBatch(const QFont& font);
    // The tag must outlive the batch (the page's TileTagCache keeps it).
    void add(const TileTag& tag);
    void paintBackings(QPainter& painter, const TrackColors& colors, const QRect& area) const;
    void paintGlyphs(QPainter& painter, const TrackColors& colors) const;
    void paintShaped(QPainter& painter, const TrackColors& colors) const;

private:
    QFont m_font;
    QString m_fontDescription; // QFont::toString(), for a font of each thread's own
    std::vector<const TileTag*> m_tags;
    std::vector<const TileTag*> m_shaped;
    QList<quint32> m_glyphIndexes;
    QList<QPointF> m_glyphPositions;
};

// The tags of one page laid out once per zoom: a repaint draws each tag's known text at its known place
// instead of measuring and shortening 2,000 names again. Tags are drawn, not kept as pictures: a picture
// per name cost the first repaint of a 2,000-name page 30 ms and a megabyte per zoom.
class TileTagCache final {
public:
    // Forgets every layout: the zoom, the font or the screen changed.
    void clear() { m_tags.clear(); }
    // The tag of `tile`, made on first use (`make` builds it).
    template <class Make>
    const TileTag& tag(int tile, int tileCount, Make make) {
        if (m_tags.size() != std::size_t(tileCount))
            m_tags.assign(std::size_t(tileCount), std::nullopt);
        auto& entry = m_tags[std::size_t(tile)];
        if (!entry)
            entry.emplace(make());
        return *entry;
    }

private:
    std::vector<std::optional<TileTag>> m_tags;
};

} // namespace stellwerk::ui
