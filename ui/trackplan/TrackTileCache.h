#pragma once

#include "trackplan/TrackColors.h"
#include "trackplan/TrackTileLook.h"

#include <QFont>
#include <QHash>
#include <QImage>
#include <QPoint>
#include <vector>

class QPainter;

namespace stellwerk::ui {

// The drawn picture of every tile look at the current tile size, so that a repaint blits pictures instead
// of stroking paths and laying out text for each of thousands of tiles. The pictures are drawn by
// TrackTilePainter at the screen's device pixel ratio and thrown away when the size, the colours, the
// font or the ratio change, so the plan stays anti-aliased vector art at every zoom.
class TrackTileCache final {
public:
    // How far, in pixels, a tile's strokes may reach over its cell's edges.
    static constexpr int Overhang = 2;

    // Starts a repaint; forgets every picture when anything they were drawn with changed.
    void prepare(int tileSize, qreal devicePixelRatio, const TrackColors& colors, const QFont& font);
    // The area the tile's picture covers when its cell's top left corner is at `cell` (labels run
    // beyond their cell).
    QRect area(const TrackTileLook& look, QPoint cell);
    void paint(QPainter& painter, QPoint cell, const TrackTileLook& look);
    // A tile's picture where it lands: a copy that stays valid whatever the cache does next, so that
    // other threads may blit it (QImage copies share their pixels).
    struct Placed {
        QImage image; // null where the tile draws nothing
        QPoint at;
        QRect area() const { return {at, image.deviceIndependentSize().toSize()}; }
        void paint(QPainter& painter) const;
    };
    Placed placed(const TrackTileLook& look, QPoint cell);
    // Draws the pictures `looks` will need and that are not drawn yet, on all of the machine's cores (up
    // to four: PaintThreads): a page's first paint draws hundreds at once. Labels are left to paint(), on
    // this thread.
    void drawAhead(const std::vector<TrackTileLook>& looks);
    int size() const { return int(m_pictures.size()); }

private:
    struct Key {
        QString type;
        QString text;
        int category = 0;
        int rotation = 0;
        int position = -1;
        bool occupied = false;
        bool running = false;
        bool onRoute = false;
        size_t hash = 0; // of the fields above, made once: a page's paint looks up thousands of keys
        bool operator==(const Key&) const = default;
        friend size_t qHash(const Key& key, size_t seed = 0) { return key.hash ^ seed; }
    };
    struct Picture {
        QImage image;  // not a QPixmap: on the raster engine both are blitted alike, and images need no
                       // conversion after drawing, cropping and turning
        QPoint offset; // of the image's top left corner from the cell's
    };

    static Key keyOf(const TrackTileLook& look);
    const Picture& pictureOf(const TrackTileLook& look);
    Picture draw(const TrackTileLook& look);
    QRect pixelsOf(const TrackTileLook& look) const;
    QImage drawn(const TrackTileLook& look, const QRect& pixels) const;
    bool turnsExactly(const TrackTileLook& look) const;
    Picture turned(const TrackTileLook& look);
    Picture turn(const Picture& upright, int rotation) const;
    // make(0) .. make(count - 1), spread over the paint threads (this one among them).
    template <class Make>
    static std::vector<Picture> onAllCores(std::size_t count, Make make);
    void insert(const std::vector<TrackTileLook>& looks, std::vector<Picture> pictures);
    QRectF cell() const { return {0, 0, double(m_tileSize), double(m_tileSize)}; }
    Picture cropped(const QImage& image, QPoint offset) const;

    static constexpr int MinimumAhead = 32;      // fewer missing pictures are drawn as they are met
    static constexpr int MaximumPictures = 8192; // labels each have their own; start afresh beyond this

    QHash<Key, Picture> m_pictures;
    int m_tileSize = 0;
    qreal m_devicePixelRatio = 1.0;
    TrackColors m_colors;
    QFont m_font;
};

} // namespace stellwerk::ui
