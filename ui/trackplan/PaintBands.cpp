#include "trackplan/PaintBands.h"

#include "trackplan/PaintThreads.h"

#include <QImage>
#include <QPaintEngine>
#include <QPainter>
#include <QRegion>
#include <atomic>
#include <cmath>
#include <vector>

namespace stellwerk::ui {
namespace {

std::atomic<bool> enabled{true};

// One band: its rows in logical and in device coordinates.
struct Band {
    QRect area;
    int firstRow = 0; // of the device image
    int rows = 0;
};

std::vector<Band> bandsOf(const QRect& area, std::size_t count, const QTransform& toDevice, int imageHeight) {
    std::vector<Band> bands;
    const double ratio = toDevice.m22();
    for (std::size_t k = 0; k < count; ++k) {
        const int top = area.top() + int(std::size_t(area.height()) * k / count);
        const int bottom = area.top() + int(std::size_t(area.height()) * (k + 1) / count); // exclusive
        const int first = std::max(0, int(std::lround(top * ratio + toDevice.dy())));
        const int end = std::min(imageHeight, int(std::lround(bottom * ratio + toDevice.dy())));
        if (end > first)
            bands.push_back({QRect(area.left(), top, area.width(), bottom - top), first, end - first});
    }
    return bands;
}

} // namespace

void PaintBands::setEnabled(bool on) {
    enabled = on;
}

int PaintBands::paint(QPainter& painter, const QRect& area, const Paint& paint) {
    const std::size_t count = std::min<std::size_t>(enabled ? PaintThreads::count() : 1,
                                                    std::size_t(area.height() / MinimumHeight));
    QImage* image = count > 1 ? imageBehind(painter) : nullptr;
    if (!image || !paintsWholePixels(painter, *image)) {
        paint(painter, area);
        return 1;
    }
    const QTransform toDevice = painter.deviceTransform();
    QRegion allowed = painter.hasClipping() ? painter.clipRegion() : QRegion(area);
    if (const QRegion system = painter.paintEngine()->systemClip(); !system.isEmpty())
        allowed &= toDevice.inverted().map(system);
    const std::vector<Band> bands = bandsOf(area, count, toDevice, image->height());
    uchar* const pixels = image->bits(); // the image is not shared (imageBehind): no copy is made
    const qsizetype stride = image->bytesPerLine();
    const double ratio = image->devicePixelRatio();
    PaintThreads::run(bands.size(), [&](std::size_t k) {
        const Band& band = bands[k];
        QImage rows(pixels + band.firstRow * stride, image->width(), band.rows, stride, image->format());
        rows.setDevicePixelRatio(ratio);
        QPainter bandPainter(&rows);
        bandPainter.setTransform(
            QTransform::fromTranslate(toDevice.dx() / ratio, (toDevice.dy() - band.firstRow) / ratio));
        bandPainter.setClipRegion(allowed & band.area);
        paint(bandPainter, band.area);
    });
    return int(bands.size());
}

// The image the painter's engine writes into, where it writes straight into an unshared 32-bit image.
QImage* PaintBands::imageBehind(QPainter& painter) {
    QPaintEngine* engine = painter.paintEngine();
    if (!engine || engine->type() != QPaintEngine::Raster || !engine->paintDevice() ||
        engine->paintDevice()->devType() != QInternal::Image)
        return nullptr;
    auto* image = static_cast<QImage*>(engine->paintDevice());
    return image->depth() == 32 && image->isDetached() ? image : nullptr;
}

// True when the painter maps logical pixels to whole device pixels: a translation by whole pixels and
// the image's own whole-numbered device pixel ratio.
bool PaintBands::paintsWholePixels(const QPainter& painter, const QImage& image) {
    const QTransform t = painter.deviceTransform();
    const double ratio = image.devicePixelRatio();
    return t.type() <= QTransform::TxScale && ratio == std::floor(ratio) && t.m11() == ratio &&
           t.m22() == ratio && t.dx() == std::floor(t.dx()) && t.dy() == std::floor(t.dy());
}

} // namespace stellwerk::ui
