#include "trackplan/BlockShades.h"

#include "common/Contrast.h"
#include "trackplan/TrackColors.h"

namespace stellwerk::ui {
namespace {

// Okabe and Ito's colours for colour-blind readers, darkened on a light plan for the white names on them.
QColor colourOf(BlockShade shade, bool dark) {
    switch (shade) {
    case BlockShade::Plain:
        break;
    case BlockShade::Free:
        return dark ? QColor(64, 196, 150) : QColor(0, 125, 90); // bluish green
    case BlockShade::Reserved:
        return dark ? QColor(86, 180, 233) : QColor(0, 96, 160); // blue
    case BlockShade::Occupied:
        return dark ? QColor(240, 128, 48) : QColor(196, 78, 0); // vermilion
    case BlockShade::Ghost:
        return dark ? QColor(210, 140, 190) : QColor(136, 34, 102); // reddish purple
    case BlockShade::Fault:
        return dark ? QColor(240, 200, 60) : QColor(20, 20, 20); // black on light, yellow on dark
    }
    return {};
}

Qt::BrushStyle patternOf(BlockShade shade) {
    switch (shade) {
    case BlockShade::Reserved:
        return Qt::BDiagPattern;
    case BlockShade::Ghost:
        return Qt::DiagCrossPattern;
    case BlockShade::Fault:
        return Qt::Dense5Pattern;
    default:
        return Qt::SolidPattern;
    }
}

} // namespace

BlockShadeLook BlockShadeLook::of(BlockShade shade, const TrackColors& colors) {
    if (shade == BlockShade::Plain)
        return {colors.block, QBrush(colors.blockBand), colors.blockText};
    const bool dark = colors.background.lightnessF() < 0.5;
    const QColor edge = colourOf(shade, dark);
    QColor band = edge;
    const Qt::BrushStyle pattern = patternOf(shade);
    // A pattern in the full colour but faded towards the page; solid fills translucent, a free block faint.
    band.setAlpha(pattern != Qt::SolidPattern ? 150 : shade == BlockShade::Free ? 30 : 70);
    const QColor text = Contrast::ratio(Qt::white, edge) >= Contrast::ratio(Qt::black, edge)
                            ? QColor(Qt::white)
                            : QColor(Qt::black);
    return {edge, QBrush(band, pattern), text};
}

} // namespace stellwerk::ui
