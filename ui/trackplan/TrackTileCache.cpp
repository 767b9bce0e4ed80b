#include "trackplan/TrackTileCache.h"

#include "trackplan/PaintThreads.h"
#include "trackplan/TrackTilePainter.h"

#include <QImage>
#include <QPainter>
#include <QSet>
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
    return placed(look, cell).area();
}

void TrackTileCache::paint(QPainter& painter, QPoint cell, const TrackTileLook& look) {
    placed(look, cell).paint(painter);
}

TrackTileCache::Placed TrackTileCache::placed(const TrackTileLook& look, QPoint cell) {
    const Picture& picture = pictureOf(look);
    return {picture.image, cell + picture.offset};
}

void TrackTileCache::Placed::paint(QPainter& painter) const {
    if (!image.isNull())
        painter.drawImage(at, image);
}

TrackTileCache::Key TrackTileCache::keyOf(const TrackTileLook& look) {
    const bool label = look.category == cs2config::TrackCategory::Text;
    Key key{look.type,          label ? look.text : QString(),
            int(look.category), look.rotation,
            look.position,      look.occupied,
            look.running,       look.onRoute};
    key.hash = qHashMulti(0, key.type, key.text, key.category, key.rotation, key.position, key.occupied,
                          key.running, key.onRoute);
    return key;
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
    if ((look.rotation & 3) != 0 && turnsExactly(look))
        return turned(look);
    const QRect pixels = pixelsOf(look);
    return cropped(drawn(look, pixels), pixels.topLeft());
}

// The device's whole pixels the tile's picture may cover, relative to its cell's top left corner: a
// little room around the cell for strokes that reach over its edge.
QRect TrackTileCache::pixelsOf(const TrackTileLook& look) const {
    const QRectF reach =
        TrackTilePainter::area(cell(), look, m_font).adjusted(-Overhang, -Overhang, Overhang, Overhang);
    return {QPoint(int(std::floor(reach.left())), int(std::floor(reach.top()))),
            QPoint(int(std::ceil(reach.right())), int(std::ceil(reach.bottom())))};
}

void TrackTileCache::drawAhead(const std::vector<TrackTileLook>& looks) {
    std::vector<TrackTileLook> uprights; // drawn without the font, not drawn yet, each once
    std::vector<TrackTileLook> turns;    // to be turned from their upright pictures
    QSet<Key> seen;
    for (const TrackTileLook& look : looks) {
        const Key key = keyOf(look);
        if (!TrackTilePainter::draws(look) || TrackTilePainter::usesFont(look) || m_pictures.contains(key) ||
            seen.contains(key))
            continue;
        seen.insert(key);
        const bool turning = (look.rotation & 3) != 0 && turnsExactly(look);
        (turning ? turns : uprights).push_back(look);
        if (!turning)
            continue;
        TrackTileLook upright = look;
        upright.rotation = 0;
        if (const Key uprightKey = keyOf(upright);
            !m_pictures.contains(uprightKey) && !seen.contains(uprightKey)) {
            seen.insert(uprightKey);
            uprights.push_back(upright);
        }
    }
    if (int(uprights.size() + turns.size()) < MinimumAhead)
        return; // a few tiles: not worth starting threads
    insert(uprights, onAllCores(uprights.size(), [&](std::size_t i) {
               const QRect pixels = pixelsOf(uprights[i]);
               return cropped(drawn(uprights[i], pixels), pixels.topLeft());
           }));
    insert(turns, onAllCores(turns.size(), [&](std::size_t i) {
               TrackTileLook upright = turns[i];
               upright.rotation = 0;
               return turn(*m_pictures.constFind(keyOf(upright)), turns[i].rotation);
           }));
}

template <class Make>
std::vector<TrackTileCache::Picture> TrackTileCache::onAllCores(std::size_t count, Make make) {
    std::vector<Picture> pictures(count);
    const std::size_t threads = std::min(PaintThreads::count(), count);
    PaintThreads::run(threads, [&](std::size_t from) {
        for (std::size_t i = from; i < count; i += threads)
            pictures[i] = make(i);
    });
    return pictures;
}

void TrackTileCache::insert(const std::vector<TrackTileLook>& looks, std::vector<Picture> pictures) {
    for (std::size_t i = 0; i < looks.size(); ++i)
        m_pictures.insert(keyOf(looks[i]), std::move(pictures[i]));
}

QImage TrackTileCache::drawn(const TrackTileLook& look, const QRect& pixels) const {
    // Drawn into one image per thread, kept from picture to picture: the picture keeps a cropped copy, and
    // a new image per picture would touch new memory each time.
    const QSize size = (QSizeF(pixels.size()) * m_devicePixelRatio).toSize();
    thread_local QImage image;
    if (image.size() != size)
        image = QImage(size, QImage::Format_ARGB32_Premultiplied);
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
    return turn(pictureOf(upright), look.rotation);
}

TrackTileCache::Picture TrackTileCache::turn(const Picture& upright, int rotation) const {
    if (upright.image.isNull())
        return {};
    const double centre = m_tileSize / 2.0;
    const QTransform turn = QTransform().rotate(-90.0 * (rotation & 3));
    const QTransform aboutCentre =
        QTransform::fromTranslate(-centre, -centre) * turn * QTransform::fromTranslate(centre, centre);
    const QRectF area(upright.offset, upright.image.deviceIndependentSize());
    QImage image = upright.image.transformed(turn);
    image.setDevicePixelRatio(m_devicePixelRatio);
    return {std::move(image), aboutCentre.mapRect(area).topLeft().toPoint()};
}

// Most of a tile is empty: keeping only the part that was drawn on saves blending those pixels on
// every repaint. Crops whole logical pixels, so that the picture still lands on the device's grid.
TrackTileCache::Picture TrackTileCache::cropped(const QImage& image, QPoint offset) const {
    const int ratio = int(m_devicePixelRatio);
    if (ratio != m_devicePixelRatio) // a fractional ratio: no whole logical pixels to crop to
        return {image, offset};
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
    return {std::move(part), offset + drawn.topLeft()};
}

} // namespace stellwerk::ui
