#pragma once

#include "trackgraph/TrackGraph.h"

#include <chrono>
#include <cstdint>
#include <map>
#include <optional>

namespace stellwerk::sim {

class SimulatedStation;

// The plan's turnouts as the simulated station has them set, and which of them are moving: a turnout whose
// position changed moves for its switching time (magnetartikel.cs2 `.schaltzeit`, else 200 ms), counted in
// the train movement's own time, so that a train meeting it then derails as on a real layout.
class TurnoutWatch {
public:
    static constexpr std::chrono::milliseconds DefaultSwitchingTime{200};
    // What a turnout the station has never set and magnetartikel.cs2 does not list lies in: 1 (straight).
    static constexpr int UnknownPosition = 1;

    TurnoutWatch(const SimulatedStation& station, const trackgraph::TrackGraph& graph);

    // Reads the positions the station has now: one that changed starts moving, and `elapsed` passes for
    // those that move. Call once per step of the movement.
    void update(std::chrono::milliseconds elapsed);
    // A turnout's position by keyboard number; nullopt while it moves.
    std::optional<int> settled(std::int64_t article) const;
    bool moving(std::int64_t article) const;
    // settled() as the track graph asks for it.
    trackgraph::PositionOf positionOf() const;

private:
    struct Turnout {
        std::uint32_t locId = 0; // the station's accessory Loc-ID
        int position = UnknownPosition;
        std::chrono::milliseconds switchingTime{DefaultSwitchingTime};
        std::chrono::milliseconds stillMoving{0};
    };

    void add(std::int64_t article);
    int stationPosition(const Turnout& turnout) const;

    const SimulatedStation& station_;
    std::map<std::int64_t, Turnout> turnouts_; // by keyboard number
};

} // namespace stellwerk::sim
