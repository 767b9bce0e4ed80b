#pragma once

#include "trackgraph/Problem.h"
#include "trackgraph/TrackTiles.h"

#include <optional>
#include <utility>
#include <vector>

namespace stellwerk::trackgraph {

// Pairs the page arrows (`pfeil`) that carry track from one page to another. An arrow names its page by
// number (`.artikel`, as the CS2 writes it) or, failing that, by name (`.text`). An arrow whose track side
// joins no track is a button for changing pages and carries nothing. Arrows from page P to Q pair with
// arrows from Q back to P, nearest first (the fewest columns and rows apart; a page continued on the next
// keeps its rows), then in plan order; an arrow left over is reported.
class PageLinks {
public:
    static PageLinks pair(const TrackTiles& tiles, ProblemList& problems);

    // The arrow this one continues at; nullopt when it has none.
    std::optional<TileId> partnerOf(TileId arrow) const;
    std::size_t size() const { return partners_.size() / 2; }

private:
    struct Arrow {
        TileId tile;
        std::uint32_t from; // its own page
        std::uint32_t to;   // the page it names
    };

    static std::optional<Arrow> trackArrow(const TrackTiles& tiles, TileId tile, ProblemList& problems);
    void pairArrows(const TrackTiles& tiles, const std::vector<Arrow>& arrows);

    std::vector<std::pair<TileId, TileId>> partners_; // both directions, sorted
};

} // namespace stellwerk::trackgraph
