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

TrackTileCache::Key TrackTileCache::keyOf(const TrackTileLook& look) {
    const bool label = look.category == cs2config::TrackCategory::Text;
    return {look.type,          label ? look.text : QString(),
            int(look.category), look.rotation,
            look.position,      look.occupied,
            look.running,       look.onRoute};
}

const TrackTileCache::Picture& TrackTileCache::pictureOf(const TrackTileLook& look) {
    const Key key = keyOf(look);
    auto it = m_pictures.find(key);
    if (it == m_pictures.end())
        it = m_pictures.insert(key, draw(look));
    return *it;
}

TrackTileCache::Picture TrackTileCache::draw(const TrackTileLook& look) {
    if (!TrackTilePainter::draws(look))
        return {};
    // A little room around the cell for strokes that reach over its edge.
    const QRectF reach =
        TrackTilePainter::area(cell(), look, m_font).adjusted(-Overhang, -Overhang, Overhang, Overhang);
    const QRect pixels(QPoint(int(std::floor(reach.left())), int(std::floor(reach.top()))),
                       QPoint(int(std::ceil(reach.right())), int(std::ceil(reach.bottom()))));
    if ((look.rotation & 3) != 0 && turnsExactly(look))
        return turned(look);
    return cropped(drawn(look, pixels), pixels.topLeft());
}

QImage TrackTileCache::drawn(const TrackTileLook& look, const QRect& pixels) const {
    QImage image((QSizeF(pixels.size()) * m_devicePixelRatio).toSize(), QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(m_devicePixelRatio);
    image.fill(Qt::transparent);
    QPainter painter(&image);
    painter.setFont(m_font);
    painter.translate(-pixels.topLeft());
    TrackTilePainter::paint(painter, cell(), look, m_colors);
    return image;
}

// Every shape but a label is drawn unrotated and turned by the painter about the cell's centre. On a
// whole-numbered device grid, turning the unrotated picture about that centre gives the same picture and
// costs a copy instead of a drawing: a page draws each shape once, not once per rotation.
bool TrackTileCache::turnsExactly(const TrackTileLook& look) const {
    return look.category != cs2config::TrackCategory::Text &&
           m_devicePixelRatio == std::floor(m_devicePixelRatio);
}

TrackTileCache::Picture TrackTileCache::turned(const TrackTileLook& look) {
    TrackTileLook upright = look;
    upright.rotation = 0;
    const Picture& picture = pictureOf(upright);
    if (picture.pixmap.isNull())
        return {};
    const double centre = m_tileSize / 2.0;
    const QTransform turn = QTransform().rotate(-90.0 * (look.rotation & 3));
    const QTransform aboutCentre =
        QTransform::fromTranslate(-centre, -centre) * turn * QTransform::fromTranslate(centre, centre);
    const QRectF area(picture.offset, picture.pixmap.deviceIndependentSize());
    QPixmap pixmap = picture.pixmap.transformed(turn);
    pixmap.setDevicePixelRatio(m_devicePixelRatio);
    return {pixmap, aboutCentre.mapRect(area).topLeft().toPoint()};
}

// Most of a tile is empty: keeping only the part that was drawn on saves blending those pixels on
// every repaint. Crops whole logical pixels, so that the picture still lands on the device's grid.
TrackTileCache::Picture TrackTileCache::cropped(const QImage& image, QPoint offset) const {
    const int ratio = int(m_devicePixelRatio);
    if (ratio != m_devicePixelRatio) // a fractional ratio: no whole logical pixels to crop to
        return {QPixmap::fromImage(image), offset};
    const int width = image.width(), height = image.height();
    int left = width, top = height, right = -1, bottom = -1;
    for (int y = 0; y < height; ++y) {
        const auto* line = reinterpret_cast<const QRgb*>(image.constScanLine(y));
        int first = 0;
        while (first < width && qAlpha(line[first]) == 0)
            ++first;
        if (first == width)
            continue; // an empty line
        int last = width - 1;
        while (qAlpha(line[last]) == 0)
            --last;
        left = std::min(left, first);
        right = std::max(right, last);
        top = std::min(top, y);
        bottom = y;
    }
    const QRect drawn(QPoint(left / ratio, top / ratio), QPoint(right / ratio, bottom / ratio));
    if (right < 0)
        return {}; // nothing drawn
    QImage part = image.copy(QRect(drawn.topLeft() * ratio, drawn.size() * ratio));
    part.setDevicePixelRatio(m_devicePixelRatio);
    return {QPixmap::fromImage(std::move(part)), offset + drawn.topLeft()};
}

} // namespace stellwerk::ui
