#pragma once

#include <QColor>

class QPalette;

namespace stellwerk::ui {

// The track plan's colours, derived from the desktop's palette so that the plan reads well on light
// and dark themes alike.
struct TrackColors {
    QColor background;
    QColor grid;
    QColor track;    // plain track and the leg a turnout is set to
    QColor dim;      // the legs a turnout is not set to, unlit lamps
    QColor occupied; // an occupied S88 contact
    QColor red;      // lamps and buttons
    QColor green;
    QColor yellow;
    QColor white;
    QColor button;    // route buttons and output buttons
    QColor highlight; // a running route
    QColor text;
    QColor block;     // the outline of a block and the tab with its name
    QColor blockBand; // the translucent band over a block's tiles
    QColor blockText; // a block's name on its tab
    QColor problem;   // the marker of a tile with a problem in the drawing

    static TrackColors from(const QPalette& palette);
    bool operator==(const TrackColors&) const = default;
};

} // namespace stellwerk::ui
