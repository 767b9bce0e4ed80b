#pragma once

#include "trackgraph/TrackGraph.h"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace stellwerk::automation {

// A piece of track a train's body lies on behind its front block.
struct BodySegment {
    bool isBlock = true;
    int id = 0; // block or connection id
    int lengthMm = 0;
};

// Where a train is: the block its front is in, the end it runs towards, how far its front is from the
// block's other end (at least: the contacts it has reached say so), and what its length still covers behind.
struct TrainBody {
    int frontBlock = 0;
    trackgraph::End towards = trackgraph::End::B;
    int frontMm = 0;
    int lengthMm = 200;
    std::vector<BodySegment> behind; // rear first
};

// What one contact turning occupied meant.
struct Sighting {
    enum class Kind : std::uint8_t {
        None,    // a contact of no block, or one a train already covers
        Moved,   // a further contact of the block the train's front is in
        Entered, // the front entered the block the train was expected to enter
        Ghost,   // nobody can have reached this block: an unknown occupant
    };
    Kind kind = Kind::None;
    std::uint32_t locId = 0;
    int block = 0;
    int connection = 0;   // Entered: the connection passed
    int contactIndex = 0; // Moved, Entered: the contact's place in the direction of travel (0: first)
};

// The way a train would go next as the automation or the turnouts say: the connection and the block.
struct NextBlock {
    int connection = 0;
    int block = 0;
};
using ExpectedNext = std::function<std::optional<NextBlock>(std::uint32_t locId)>;

// Follows every placed train over the track graph from contact occupancy: a contact of the block ahead on
// its way turning occupied moves its front in; a block behind it is left once its contacts are free and
// the train's length has passed it. An occupied contact no train can have reached is an unknown occupant
// (a ghost) until its block's contacts are free again.
class Tracking {
public:
    explicit Tracking(const trackgraph::TrackGraph& graph) : graph_(graph) {}

    // Puts a train in a block, its front at the far edge of the block's contact nearest `towards` (further
    // on when the train would not fit behind it), as the simulator places it.
    void place(std::uint32_t locId, int block, trackgraph::End towards, int lengthMm);
    void remove(std::uint32_t locId);
    // The front has gone on to at least `frontMm` in its block (a stop by the distance, with no contact).
    void advanced(std::uint32_t locId, int frontMm);
    // The train changes direction where it stands: its rear becomes its front, facing the other end. Only a
    // train whole inside its front block can (false, nothing changed, otherwise).
    bool reverse(std::uint32_t locId);

    Sighting occupied(const trackgraph::ContactKey& contact, const ExpectedNext& expected);
    // A contact turned free; the ghost block that is free now, if any.
    std::optional<int> freed(const trackgraph::ContactKey& contact);
    // The station's occupancy read again: everything before is forgotten, ghosts found anew (returned).
    std::vector<int> reread(const std::set<trackgraph::ContactKey>& occupied);

    // The pieces behind a train's rear (its length has passed them and a block's contacts are free),
    // taken off its body, rear first.
    std::vector<BodySegment> left(std::uint32_t locId);

    const TrainBody* body(std::uint32_t locId) const;
    // The train whose body covers the block (front or behind), 0 when none.
    std::uint32_t trainIn(int block) const;
    std::vector<int> blocksOf(std::uint32_t locId) const;
    bool isGhost(int block) const { return ghosts_.contains(block); }
    const std::set<int>& ghosts() const { return ghosts_; }
    bool blockOccupied(int block) const;
    // A contact's stretch in the direction of travel, from the end a train enters through.
    std::pair<int, int> contactSpan(int block, std::size_t index, trackgraph::End towards) const;
    // The contact's place in the direction of travel.
    std::size_t travelIndex(int block, const trackgraph::ContactKey& contact, trackgraph::End towards) const;

private:
    Sighting enter(std::uint32_t locId, TrainBody& body, const NextBlock& next,
                   const trackgraph::ContactKey& contact);

    const trackgraph::TrackGraph& graph_;
    std::map<std::uint32_t, TrainBody> bodies_;
    std::set<trackgraph::ContactKey> occupied_;
    std::set<int> ghosts_;
};

} // namespace stellwerk::automation
