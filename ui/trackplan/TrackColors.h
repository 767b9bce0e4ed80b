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

    static TrackColors from(const QPalette& palette);
    bool operator==(const TrackColors&) const = default;
};

} // namespace stellwerk::ui
