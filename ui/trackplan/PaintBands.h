#pragma once

#include <QRect>
#include <functional>

class QImage;
class QPainter;

namespace stellwerk::ui {

// Paints a large area in horizontal bands on all cores, each straight into its rows of the image behind
// the painter, so that filling a page and blitting its thousands of tiles take a fraction of the time.
// Every band paints exactly what one painter would have painted in its rows. Where the painter does not
// paint on a plain image (a pixmap, a printer, a picture), at a fractional device pixel ratio or with a
// turned or scaled view, the area is painted in one band by the painter itself.
class PaintBands final {
public:
    // paint(bandPainter, band) for bands that cover `area` (the painter's logical coordinates); each band's
    // painter is clipped to its band and to where `painter` may paint. Returns how many bands there were.
    using Paint = std::function<void(QPainter& painter, const QRect& band)>;
    static int paint(QPainter& painter, const QRect& area, const Paint& paint);

    // Off: every area in one band (tests compare the two).
    static void setEnabled(bool enabled);

    // Bands are at least this many logical pixels high: a small repaint is not worth the threads.
    static constexpr int MinimumHeight = 64;

private:
    static QImage* imageBehind(QPainter& painter);
    static bool paintsWholePixels(const QPainter& painter, const QImage& image);
};

} // namespace stellwerk::ui
