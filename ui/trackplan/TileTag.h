#pragma once

#include <QFont>
#include <QPixmap>
#include <QRect>
#include <QString>
#include <optional>
#include <utility>
#include <vector>

class QPainter;

namespace stellwerk::model {
struct LayoutTile;
}

namespace stellwerk::ui {

struct TrackColors;

// The name an element carries in its file (`.text`: a turnout's number, a signal's name, an S88 contact's
// number, a route's name), drawn small on a light backing at the tile's top left (under a route button)
// and shortened to the tile, so that the plan reads like the station's own. Too small a zoom draws none.
class TileTag final {
public:
    // Tiles smaller than this carry no tag: the text would not be readable.
    static constexpr int MinimumTile = 26;

    TileTag(const model::LayoutTile& tile, const QRect& cell, const QFont& font);

    bool shown() const { return !m_text.isEmpty(); }
    // Where the tag is drawn, inside the tile; empty when none is shown.
    QRect rect() const { return m_rect; }
    QString text() const { return m_text; }
    void paint(QPainter& painter, const TrackColors& colors) const;
    // The tag drawn once into a picture of rect()'s size, for TileTagCache.
    QPixmap picture(const TrackColors& colors, double devicePixelRatio) const;

private:
    QFont m_font;
    QString m_text;
    QRect m_rect;
};

// The tags of one page drawn once per zoom: a repaint puts pictures on the plan instead of laying out text
// (2,000 named elements would cost a repaint about 20 ms otherwise).
class TileTagCache final {
public:
    // Forgets every picture: the zoom, the font, the colours or the screen changed.
    void clear() { m_tags.clear(); }
    // The tag of `tile`, made on first use (`make` builds it).
    template <class Make>
    const std::pair<QRect, QPixmap>& tag(int tile, int tileCount, Make make) {
        if (m_tags.size() != std::size_t(tileCount))
            m_tags.assign(std::size_t(tileCount), std::nullopt);
        auto& entry = m_tags[std::size_t(tile)];
        if (!entry)
            entry = make();
        return *entry;
    }

private:
    std::vector<std::optional<std::pair<QRect, QPixmap>>> m_tags;
};

} // namespace stellwerk::ui
