#include "trackplan/TrackTileCache.h"

#include "trackplan/TrackTilePainter.h"

#include <QImage>
#include <QPainter>
#include <algorithm>
#include <cmath>

namespace stellwerk::ui {

void TrackTileCache::prepare(int tileSize, qreal devicePixelRatio, const TrackColors& colors,
                             const QFont& font) {
    if (tileSize == m_tileSize && devicePixelRatio == m_devicePixelRatio && colors == m_colors &&
        font == m_font && m_pictures.size() < MaximumPictures)
        return;
    m_pictures.clear();
    m_tileSize = tileSize;
    m_devicePixelRatio = devicePixelRatio;
    m_colors = colors;
    m_font = font;
}

QRect TrackTileCache::area(const TrackTileLook& look, QPoint cell) {
    const Picture& picture = pictureOf(look);
    return {cell + picture.offset, picture.pixmap.deviceIndependentSize().toSize()};
}

void TrackTileCache::paint(QPainter& painter, QPoint cell, const TrackTileLook& look) {
    const Picture& picture = pictureOf(look);
    if (!picture.pixmap.isNull())
        painter.drawPixmap(cell + picture.offset, picture.pixmap);
}

const TrackTileCache::Picture& TrackTileCache::pictureOf(const TrackTileLook& look) {
    const bool label = look.category == cs2config::TrackCategory::Text;
    const Key key{look.type,          label ? look.text : QString(),
                  int(look.category), look.rotation,
                  look.position,      look.occupied,
                  look.running,       look.onRoute};
    auto it = m_pictures.find(key);
    if (it == m_pictures.end())
        it = m_pictures.insert(key, draw(look));
    return *it;
}

TrackTileCache::Picture TrackTileCache::draw(const TrackTileLook& look) const {
    if (!TrackTilePainter::draws(look))
        return {};
    const QRectF cell(0, 0, m_tileSize, m_tileSize);
    // A little room around the cell for strokes that reach over its edge.
    const QRectF reach =
        TrackTilePainter::area(cell, look, m_font).adjusted(-Overhang, -Overhang, Overhang, Overhang);
    const QRect pixels(QPoint(int(std::floor(reach.left())), int(std::floor(reach.top()))),
                       QPoint(int(std::ceil(reach.right())), int(std::ceil(reach.bottom()))));
    QImage image((QSizeF(pixels.size()) * m_devicePixelRatio).toSize(), QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(m_devicePixelRatio);
    image.fill(Qt::transparent);
    {
        QPainter painter(&image);
        painter.setFont(m_font);
        painter.translate(-pixels.topLeft());
        TrackTilePainter::paint(painter, cell, look, m_colors);
    }
    return cropped(image, pixels.topLeft());
}

// Most of a tile is empty: keeping only the part that was drawn on saves blending those pixels on
// every repaint. Crops whole logical pixels, so that the picture still lands on the device's grid.
TrackTileCache::Picture TrackTileCache::cropped(const QImage& image, QPoint offset) const {
    const int ratio = int(m_devicePixelRatio);
    if (ratio != m_devicePixelRatio) // a fractional ratio: no whole logical pixels to crop to
        return {QPixmap::fromImage(image), offset};
    int left = image.width(), top = image.height(), right = -1, bottom = -1;
    for (int y = 0; y < image.height(); ++y) {
        const auto* line = reinterpret_cast<const QRgb*>(image.constScanLine(y));
        for (int x = 0; x < image.width(); ++x)
            if (qAlpha(line[x]) != 0) {
                left = std::min(left, x);
                right = std::max(right, x);
                top = std::min(top, y);
                bottom = std::max(bottom, y);
            }
    }
    const QRect drawn(QPoint(left / ratio, top / ratio), QPoint(right / ratio, bottom / ratio));
    if (right < 0)
        return {}; // nothing drawn
    QImage part = image.copy(QRect(drawn.topLeft() * ratio, drawn.size() * ratio));
    part.setDevicePixelRatio(m_devicePixelRatio);
    return {QPixmap::fromImage(std::move(part)), offset + drawn.topLeft()};
}

} // namespace stellwerk::ui
