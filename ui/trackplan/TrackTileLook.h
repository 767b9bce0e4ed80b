#pragma once

#include "cs2config/TrackElementType.h"

#include <QString>

namespace stellwerk::ui {

// What a tile shows at this moment: its element and the railway's state of what it is linked to.
struct TrackTileLook {
    QString type;
    cs2config::TrackCategory category = cs2config::TrackCategory::Empty;
    int rotation = 0;      // counter-clockwise quarter turns, as CS2 files and their renderers use them
    int position = -1;     // the accessory's confirmed position; -1 when not known
    bool occupied = false; // an S88 contact a train occupies
    bool running = false;  // a route button whose route runs
    QString text;
    bool onRoute = false;  // part of a set route: its button, or an accessory it holds
    QString occupant = {}; // the locomotive on an occupied contact, where the simulator or the user says
};

} // namespace stellwerk::ui
