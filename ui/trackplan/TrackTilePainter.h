#pragma once

#include <QRectF>

class QFont;

class QPainter;

namespace stellwerk::ui {

struct TrackColors;
struct TrackTileLook;

// Draws one tile of the track plan, any element type in any rotation, as anti-aliased vector paths
// that scale with the tile. The shapes are looked up in a table by the element's `.typ` word.
class TrackTilePainter {
public:
    static void paint(QPainter& painter, const QRectF& cell, const TrackTileLook& look,
                      const TrackColors& colors);
    // Whether the tile shows anything at all (an empty tile does not).
    static bool draws(const TrackTileLook& look);
    // Whether drawing the tile needs the font (labels, the "?" of an unknown type): only those are left
    // to the GUI thread when pictures are drawn on several threads.
    static bool usesFont(const TrackTileLook& look);
    // The area the tile draws into: its cell, or for a label the text that runs beyond it.
    static QRectF area(const QRectF& cell, const TrackTileLook& look, const QFont& font);
};

} // namespace stellwerk::ui
