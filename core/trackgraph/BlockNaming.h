#pragma once

#include "cs2config/AccessoryFile.h"
#include "cs2config/RouteFile.h"
#include "trackgraph/TrackGraph.h"
#include "trackgraph/TrackTiles.h"

#include <optional>
#include <string>

namespace stellwerk::trackgraph {

// Names blocks and signals from what the pages and files say about them: a block after its first contact
// with a label (`.text`), else a route button beside its tiles (its label, else the route's name in
// fahrstrassen.cs2), else a signal on it, else "Block <contact number>".
class BlockNaming {
public:
    BlockNaming(const TrackTiles& tiles, const cs2config::AccessoryFile* accessories,
                const cs2config::RouteFile* routes)
        : tiles_(tiles), accessories_(accessories), routes_(routes) {}

    std::string blockName(const Block& block) const;
    // The tile's label, else the name of its article in magnetartikel.cs2; empty when neither says.
    std::string signalName(const Tile& tile) const;
    // A route's name in fahrstrassen.cs2; empty without one.
    std::string routeName(std::int64_t route) const;

private:
    std::optional<std::string> routeBeside(const Block& block) const;

    const TrackTiles& tiles_;
    const cs2config::AccessoryFile* accessories_;
    const cs2config::RouteFile* routes_;
};

} // namespace stellwerk::trackgraph
