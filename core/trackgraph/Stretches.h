#pragma once

#include "trackgraph/Problem.h"
#include "trackgraph/TrackJoints.h"

#include <cstdint>
#include <vector>

namespace stellwerk::trackgraph {

// One tile's piece of track in the direction of travel: entered through `entry`, left through `exit`.
struct TrackStep {
    TileId tile = 0;
    std::uint8_t leg = 0; // index into the tile's legs
    Port entry = Port::West;
    Port exit = Port::East;
    int lengthMm = 0;

    friend bool operator==(const TrackStep&, const TrackStep&) = default;
};

// What ends a stretch.
enum class StretchEndKind : std::uint8_t { Junction, BufferStop, Turntable, OpenEnd };

struct StretchEnd {
    StretchEndKind kind = StretchEndKind::OpenEnd;
    TileId junction = 0;   // the turnout or crossing (Junction)
    Port port = Port::End; // the junction's port the stretch meets
};

// Track without a junction: the tiles from one turnout, crossing, buffer stop or open end to the next, in
// the order of the tiles it was first met at. A loop without any junction has no ends.
struct Stretch {
    std::vector<TrackStep> steps;
    StretchEnd first; // beyond steps.front().entry
    StretchEnd last;  // beyond steps.back().exit
    bool loop = false;
};

// Cuts the track of every page into stretches and finds the tiles that join nothing. Each leg of a tile
// that is not a junction lies on exactly one stretch; a stretch runs from its end that comes first in plan
// order (its tile, then its port).
class Stretches {
public:
    explicit Stretches(const TrackJoints& joints);

    // The tiles that join no track on any side (they are left out of the graph).
    const std::vector<bool>& isolated() const { return isolated_; }
    // The tiles of pages that hold no track but contacts: S88 displays, left out of the graph unreported.
    const std::vector<bool>& indicators() const { return indicators_; }
    std::vector<Stretch> trace() const;

    // Reports open track ends, turnout legs leading nowhere and tiles that join nothing (once per page when
    // none of its tiles join: an S88 display page).
    void reportLooseEnds(ProblemList& problems) const;

private:
    void leaveOutIndicatorPages();
    static void inPlanOrder(Stretch& stretch);
    Stretch traceFrom(TileId tile, std::uint8_t leg, std::vector<std::uint8_t>& visited) const;
    // Walks on from a port until a junction or an end; false when it came back to `start`.
    bool extend(TrackStep from, std::vector<TrackStep>& steps, StretchEnd& end, const TrackStep& start,
                std::vector<std::uint8_t>& visited) const;
    void reportTile(TileId tile, ProblemList& problems) const;
    void reportIsolated(ProblemList& problems) const;
    void reportAlone(std::uint32_t page, const std::vector<TileId>& alone, bool joinedTrack,
                     ProblemList& problems) const;

    const TrackJoints& joints_;
    const TrackTiles& tiles_;
    std::vector<bool> isolated_;
    std::vector<bool> indicators_;
};

// The step through a leg of a tile entered through `entry`.
TrackStep stepThrough(const TrackTiles& tiles, TileId tile, std::uint8_t leg, Port entry);

} // namespace stellwerk::trackgraph
