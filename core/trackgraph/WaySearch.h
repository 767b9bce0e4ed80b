#pragma once

#include "trackgraph/Problem.h"
#include "trackgraph/Stretches.h"
#include "trackgraph/TrackGraph.h"
#include "trackgraph/TrackJoints.h"

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace stellwerk::trackgraph {

// One end of one block piece (BlockPieces.h): the piece's index and its side (0 where its steps begin).
struct PieceSide {
    std::uint32_t piece = 0;
    std::uint8_t side = 0;
};

// The piece ends by the tile and port a train leaves (or enters) them through.
class PieceEndIndex {
public:
    void add(TileId tile, Port port, PieceSide side);
    void sort();
    std::optional<PieceSide> find(TileId tile, Port port) const;

private:
    std::vector<std::pair<std::uint32_t, PieceSide>> entries_;
};

// A way found from one piece end to another; TrackGraph's connections are made from these.
struct RawWay {
    PieceSide from;
    PieceSide to;
    std::vector<TrackStep> path;
    std::vector<TurnoutOnWay> turnouts;
    std::vector<TileId> crossings;
    std::vector<SignalOnTrack> signalsAlong; // names are filled in later
};

// Every way a train can take from a piece end to the next piece end, through turnouts (each leg it may
// take, trailing ones only in the position that lets it through), crossings and track without contact,
// never over a leg twice. Bounded per end: at most MaxWays ways and MaxSteps tiles visited, else the
// search stops and says so.
class WaySearch {
public:
    static constexpr std::size_t MaxWays = 64;
    static constexpr std::size_t MaxSteps = 20000;

    WaySearch(const TrackJoints& joints, const PieceEndIndex& ends, ProblemList& problems);

    void from(PieceSide start, TileId tile, Port port, std::vector<RawWay>& ways);

private:
    struct Undo {
        bool turnout = false;
        bool crossing = false;
        bool signal = false;
        std::optional<std::size_t> maskIndex; // the article mask this step narrowed
        std::uint8_t previousMask = 0;
        bool newMask = false;
    };

    void explore(TileId tile, Port exit);
    std::vector<std::uint8_t> legsInto(TileId tile, Port entry) const;
    bool enter(TileId tile, std::uint8_t leg, Port entry);
    bool narrow(const Tile& tile, TileId id, const Leg& leg, Undo& undo);
    void leave();
    void record(PieceSide to);
    bool exhausted() const { return ways_->size() - waysAtStart_ >= MaxWays || steps_ >= MaxSteps; }

    const TrackJoints& joints_;
    const TrackTiles& tiles_;
    const PieceEndIndex& ends_;
    ProblemList& problems_;
    std::vector<std::uint8_t> onPath_; // legs on the current path, a bit per leg of each tile
    std::vector<std::pair<std::int64_t, std::uint8_t>> masks_; // article (or -1 - tile) -> positions left
    std::vector<TrackStep> path_;
    std::vector<Undo> undo_;
    std::vector<TurnoutOnWay> turnouts_;
    std::vector<TileId> crossings_;
    std::vector<SignalOnTrack> signals_;
    int distanceMm_ = 0;
    PieceSide start_;
    std::vector<RawWay>* ways_ = nullptr;
    std::size_t waysAtStart_ = 0;
    std::size_t steps_ = 0;
};

} // namespace stellwerk::trackgraph
