#pragma once

#include <QColor>

namespace stellwerk::ui {

// Greys that still read: the contrast ratio of two colours as the web's accessibility guidelines define it
// (1 to 21), and a colour faded towards its background only as far as a ratio allows. Greyed controls
// ("not reported", disabled) take their colours from here instead of the style's pale disabled greys.
class Contrast final {
public:
    static constexpr double ForText = 4.5;
    static constexpr double ForDrawings = 3.0;

    static double ratio(const QColor& a, const QColor& b);
    // `a` mixed into `b`: weight 1 is `a`, 0 is `b`.
    static QColor mix(const QColor& a, const QColor& b, double weight);
    // How much of `foreground` (1: all, at least 0.5) a greyed colour keeps over `background` to keep
    // `wanted` contrast: the weight for mix(), or the opacity of a drawing in that colour.
    static double keptFor(const QColor& foreground, const QColor& background, double wanted);
    // `foreground` faded towards `background` (at most halfway), keeping at least `wanted` contrast; the
    // foreground itself when even that is too faint.
    static QColor faded(const QColor& foreground, const QColor& background, double wanted);
};

} // namespace stellwerk::ui
