#include "trackplan/TrackColors.h"

#include <QPalette>

namespace stellwerk::ui {
namespace {

QColor mixed(const QColor& a, const QColor& b, double t) {
    return QColor::fromRgbF(float(a.redF() * (1 - t) + b.redF() * t),
                            float(a.greenF() * (1 - t) + b.greenF() * t),
                            float(a.blueF() * (1 - t) + b.blueF() * t));
}

} // namespace

TrackColors TrackColors::from(const QPalette& palette) {
    const QColor base = palette.color(QPalette::Base);
    const QColor text = palette.color(QPalette::Text);
    const bool dark = base.lightnessF() < 0.5;
    TrackColors colors;
    colors.background = base;
    colors.grid = mixed(base, text, 0.07);
    colors.track = mixed(text, base, 0.1);
    colors.dim = mixed(text, base, 0.72);
    colors.occupied = dark ? QColor(255, 112, 67) : QColor(214, 48, 39);
    colors.red = dark ? QColor(255, 82, 82) : QColor(211, 47, 47);
    colors.green = dark ? QColor(105, 240, 130) : QColor(46, 160, 67);
    colors.yellow = dark ? QColor(255, 213, 79) : QColor(230, 160, 0);
    colors.white = dark ? QColor(240, 240, 240) : QColor(250, 250, 250);
    colors.button = palette.color(QPalette::Button);
    colors.highlight = palette.color(QPalette::Highlight);
    colors.text = text;
    // Violet: no state of the plan is drawn in it (red occupied, green and yellow lamps, blue routes).
    colors.block = dark ? QColor(206, 147, 216) : QColor(123, 31, 162);
    colors.blockBand = colors.block;
    colors.blockBand.setAlpha(dark ? 60 : 38);
    colors.blockText = dark ? QColor(30, 10, 36) : QColor(255, 255, 255);
    colors.problem = QColor(242, 178, 51); // amber, as the after-trouble strip: readable on light and dark
    return colors;
}

} // namespace stellwerk::ui
