#include "trackgraph/TrackJoints.h"

namespace stellwerk::trackgraph {

Joint TrackJoints::beyond(TileId tile, Port port) const {
    if (port == Port::End)
        return {tiles_.tile(tile).role() == TileRole::Turntable ? Beyond::Turntable : Beyond::BufferStop};
    if (port == Port::Link) {
        if (const std::optional<TileId> partner = links_.partnerOf(tile))
            return {Beyond::Track, *partner, Port::Link};
        return {};
    }
    if (const std::optional<TileId> next = tiles_.joinedAt(tile, port))
        return {Beyond::Track, *next, facing(port)};
    return {};
}

} // namespace stellwerk::trackgraph
