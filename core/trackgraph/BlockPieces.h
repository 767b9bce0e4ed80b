#pragma once

#include "trackgraph/Problem.h"
#include "trackgraph/Stretches.h"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace stellwerk::trackgraph {

// What lies beyond one end of a piece of block.
struct PieceEnd {
    TileId tile = 0;                        // the piece's last tile at this end
    Port port = Port::End;                  // the port a train leaves the piece through
    StretchEnd stretchEnd;                  // when the piece ends where its stretch does
    std::optional<std::uint32_t> neighbour; // the piece it touches on the same stretch (or loop)
};

// One drawing of a block: the part of a stretch around one contact (or contacts drawn side by side), cut
// from its neighbours at a signal between them or else halfway. Side 0 is where its steps begin, side 1
// where they end. A contact drawn on several pages gives a piece on each, merged into one block.
struct BlockPiece {
    std::vector<TrackStep> steps;
    std::array<PieceEnd, 2> ends;
    std::vector<std::size_t> contactSteps; // indices into steps of the contact tiles, in order

    std::uint32_t page(const TrackTiles& tiles) const { return tiles.tile(steps.front().tile).page; }
    // The side that is end a of its own drawing: the one whose tile (then port) comes first in plan order.
    int sideA() const;
};

// Cuts stretches into block pieces and reports the stretches without any contact.
class BlockCutter {
public:
    BlockCutter(const TrackTiles& tiles, ProblemList& problems) : tiles_(tiles), problems_(problems) {}

    std::vector<BlockPiece> cut(const std::vector<Stretch>& stretches);

private:
    struct Group {
        std::size_t first; // step index of its first contact
        std::size_t last;  // and of its last
    };

    void cutStretch(const Stretch& stretch, std::vector<BlockPiece>& pieces);
    std::vector<Group> groupsOf(const std::vector<TrackStep>& steps) const;
    // Where the track between two groups is cut: [begin, result) go with the earlier one.
    std::size_t cutBetween(const std::vector<TrackStep>& steps, std::size_t begin, std::size_t end) const;
    std::vector<TrackStep> loopInOrder(const Stretch& loop) const;
    void reportWithoutContact(const Stretch& stretch);
    bool isContact(const TrackStep& step) const { return tiles_.tile(step.tile).role() == TileRole::Contact; }

    const TrackTiles& tiles_;
    ProblemList& problems_;
};

// "turnout 3", "crossing at column 4, row 2", "a buffer stop", "an open end" for sentences.
std::string describeStretchEnd(const TrackTiles& tiles, const StretchEnd& end);

} // namespace stellwerk::trackgraph
