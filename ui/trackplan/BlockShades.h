#pragma once

#include <QBrush>
#include <QColor>
#include <cstdint>

namespace stellwerk::ui {

struct TrackColors;

// What a block of the plan is shaded as: plainly outlined (no automation), or the state the automation
// gives it. Each state has a colour and a pattern of its own (free an edge only, reserved hatched, occupied
// solid, an unknown occupant cross-hatched, a fault dotted), so that it reads without telling colours apart.
enum class BlockShade : std::uint8_t { Plain, Free, Reserved, Occupied, Ghost, Fault };

// The colours and patterns of the shades, from the plan's colours (light or dark); the legend draws them too.
struct BlockShadeLook {
    QColor edge; // the band's border and the tab behind the block's name
    QBrush band; // over the block's tiles, under the track
    QColor text; // the name on its tab
    bool operator==(const BlockShadeLook&) const = default;

    static BlockShadeLook of(BlockShade shade, const TrackColors& colors);
};

} // namespace stellwerk::ui
