#pragma once

#include "sim/TrainRun.h"
#include "trackgraph/TrackGraph.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::sim {

class TurnoutWatch;

// The accidents a real layout suffers and the automation must never cause.
enum class AccidentKind : std::uint8_t {
    Collision,         // two trains touching on the same track
    BufferStop,        // a train running off the end of the track: a buffer stop, an open end, a turntable
    TurnoutRunThrough, // a turnout set against a train, moving under or in front of it, or leading nowhere
};
std::string_view accidentKindName(AccidentKind kind);

// One accident: what happened, the trains it derailed, and the line stellwerk-sim prints.
struct Accident {
    AccidentKind kind = AccidentKind::Collision;
    std::vector<std::uint32_t> trains; // the Loc-IDs of the trains derailed
    // One line: the kind, the trains by name and where, e.g.
    // `collision: BR 218 Ost and V 100 2023 in block "Gleis 1"`.
    std::string text;
};

// How many accidents of each kind happened since the movement started: what tests and the automation read.
struct AccidentCounts {
    int collisions = 0;
    int bufferStops = 0;
    int turnoutsRunThrough = 0;

    int total() const { return collisions + bufferStops + turnoutsRunThrough; }
    friend bool operator==(const AccidentCounts&, const AccidentCounts&) = default;
};

// What the watch needs to know of a train.
struct TrainOnTrack {
    std::uint32_t locId = 0;
    std::string name;
    const TrainRun* run = nullptr;
    bool derailed = false;
};

// Tells the accidents of the trains on the track graph as sentences and counts them: a front that cannot go
// on, two trains touching (once: a train derailed already causes nothing more), a turnout moving under a
// train.
class AccidentWatch {
public:
    explicit AccidentWatch(const trackgraph::TrackGraph& graph) : graph_(graph) {}

    // The front could not go on; nullopt where the train only stands (a loop without any block).
    std::optional<Accident> ranInto(const TrainOnTrack& train, const RunStop& stop);
    // Every two trains whose extents overlap, at least one of them not derailed yet.
    std::vector<Accident> collisions(const std::vector<TrainOnTrack>& trains);
    // A turnout under a running train that moves or no longer sets the leg the train stands on.
    std::optional<Accident> switchedUnder(const TrainOnTrack& train, const TurnoutWatch& turnouts);

    const AccidentCounts& counts() const { return counts_; }
    // Every accident so far, in order.
    const std::vector<Accident>& log() const { return log_; }

private:
    Accident counted(AccidentKind kind, std::vector<std::uint32_t> trains, std::string text);
    std::optional<std::string> touching(const TrainOnTrack& first, const TrainOnTrack& second) const;
    std::string whereTouching(const RunExtent& extent) const;
    std::string turnoutStop(const TrainOnTrack& train, const RunStop& stop) const;
    std::string turnoutName(std::optional<std::int64_t> article) const;
    std::string placeOf(trackgraph::TileId tile) const;
    std::string beyondBlock(int block) const;

    const trackgraph::TrackGraph& graph_;
    AccidentCounts counts_;
    std::vector<Accident> log_;
};

// The counts and lines as one JSON object, for stellwerk-sim's GET /accidents:
// {"collisions":0,"bufferStops":1,"turnoutsRunThrough":0,"total":1,"accidents":["buffer stop: ..."]}.
std::string accidentsJson(const AccidentCounts& counts, const std::vector<Accident>& log);

} // namespace stellwerk::sim
