#pragma once

#include "trackgraph/PageLinks.h"
#include "trackgraph/TrackTiles.h"

#include <cstdint>

namespace stellwerk::trackgraph {

// What a train finds when it leaves a tile through a port.
enum class Beyond : std::uint8_t {
    Track,      // the next tile's track, entered through `port`
    BufferStop, // the track ends at a buffer stop inside the tile
    Turntable,  // the track ends at a turntable or transfer table
    OpenEnd,    // nothing continues the track: an empty place, a tile whose track lies elsewhere, an arrow
                // without a partner
};

struct Joint {
    Beyond kind = Beyond::OpenEnd;
    TileId tile = 0; // the next tile (Track)
    Port port = Port::End;
};

// Where the tiles' tracks meet: beside each other on a page, and from a page arrow to its partner.
class TrackJoints {
public:
    TrackJoints(const TrackTiles& tiles, const PageLinks& links) : tiles_(tiles), links_(links) {}

    Joint beyond(TileId tile, Port port) const;
    const TrackTiles& tiles() const { return tiles_; }

private:
    const TrackTiles& tiles_;
    const PageLinks& links_;
};

} // namespace stellwerk::trackgraph
