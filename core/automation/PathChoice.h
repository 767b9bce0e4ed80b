#pragma once

#include "automation/Path.h"
#include "trackgraph/TrackGraph.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace stellwerk::automation {

// What the choice may know of the railway as it stands now.
struct TrackState {
    // Whether the train may enter or pass the block: nobody else's, no other train, no ghost.
    std::function<bool(int block)> blockFree;
    // Whether the train may use the connection: nobody else's, no conflicting one reserved.
    std::function<bool(int connection)> connectionFree;
    // The end of the block another train in it faces; nullopt when none stands there.
    std::function<std::optional<trackgraph::End>(int block)> trainFacing;
    // The end another train standing in the block faces, or one whose reserved way passes it runs towards;
    // nullopt when none (unset: nobody).
    std::function<std::optional<trackgraph::End>(int block)> travelling;
};

// Chooses an automatic train's next destination and the way to it, breadth first from the end its front
// faces (at most MaxBlocks blocks ahead). The rules:
// - never into or through a block that is not free (occupied, a ghost, reserved for another train), nor over
//   a connection another train holds or that conflicts with one, nor over a turnout without a keyboard
//   number;
// - never stop in a block shorter than the train;
// - never stop in a block the train cannot leave forwards: its far end must lead on to a block that is free
//   or holds a train facing the same way (not one facing it: two trains facing each other on a single line
//   would wait for each other for ever), so trains pass only where the line has room; nor in a block from
//   which the single line ahead, up to the next place where trains can pass (a junction with two or more
//   ways that lead on), holds or is reserved for a train coming the other way;
// - of the blocks it may stop in, the nearest *station* block wins (a block with a signal facing the train,
//   or named like a station track: "Gleis", "Bahnhof", "Bf", "track", "platform", "station"); without one
//   within reach, the nearest block it may stop in.
class PathChoice {
public:
    static constexpr int MaxBlocks = 4;

    explicit PathChoice(const trackgraph::TrackGraph& graph) : graph_(graph) {}

    std::optional<Path> choose(const trackgraph::BlockEnd& front, int trainLengthMm,
                               const TrackState& state) const;

    // The way to one block (a schedule's next stop): the same rules for the blocks passed; the target must
    // be free and no shorter than the train. When no way is free all the way, the way as far along the
    // shortest route as is free, to a block the train may stop in (it goes on from there). nullopt when it
    // cannot go anywhere towards the target now.
    std::optional<Path> chooseTo(const trackgraph::BlockEnd& front, int target, int trainLengthMm,
                                 const TrackState& state) const;

    // Whether a train running towards `towards` would stop gladly in the block (see above).
    bool isStation(int block, trackgraph::End towards) const;

private:
    bool canStop(int block, trackgraph::End towards, int trainLengthMm, const TrackState& state) const;
    bool hasWayOn(int block, trackgraph::End towards, const TrackState& state) const;
    bool clearAhead(const trackgraph::BlockEnd& from, const TrackState& state) const;
    bool usable(const trackgraph::Connection& connection, const TrackState& state) const;
    std::optional<Path> routeTo(const trackgraph::BlockEnd& front, int target, const TrackState* state) const;

    const trackgraph::TrackGraph& graph_;
};

} // namespace stellwerk::automation
