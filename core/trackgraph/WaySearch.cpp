#include "trackgraph/WaySearch.h"

#include <algorithm>
#include <bit>

namespace stellwerk::trackgraph {

namespace {

std::uint32_t keyOf(TileId tile, Port port) {
    return (tile << 4) | std::uint32_t(port);
}

// The article a turnout is switched by, or a key of its own when the tile names none.
std::int64_t switchKey(const Tile& tile, TileId id) {
    return tile.accessory ? *tile.accessory : -1 - std::int64_t(id);
}

std::size_t legsTouching(const Tile& tile, Port port) {
    const auto legs = tile.shape.legs();
    return std::size_t(
        std::count_if(legs.begin(), legs.end(), [port](const Leg& leg) { return leg.touches(port); }));
}

} // namespace

void PieceEndIndex::add(TileId tile, Port port, PieceSide side) {
    entries_.push_back({keyOf(tile, port), side});
}

void PieceEndIndex::sort() {
    std::sort(entries_.begin(), entries_.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
}

std::optional<PieceSide> PieceEndIndex::find(TileId tile, Port port) const {
    const std::uint32_t key = keyOf(tile, port);
    const auto found = std::lower_bound(entries_.begin(), entries_.end(), key,
                                        [](const auto& entry, std::uint32_t k) { return entry.first < k; });
    if (found == entries_.end() || found->first != key)
        return std::nullopt;
    return found->second;
}

WaySearch::WaySearch(const TrackJoints& joints, const PieceEndIndex& ends, ProblemList& problems)
    : joints_(joints), tiles_(joints.tiles()), ends_(ends), problems_(problems), onPath_(tiles_.size(), 0) {}

void WaySearch::from(PieceSide start, TileId tile, Port port, std::vector<RawWay>& ways) {
    start_ = start;
    ways_ = &ways;
    waysAtStart_ = ways.size();
    steps_ = 0;
    explore(tile, port);
    if (exhausted())
        problems_.add(ProblemKind::TooManyWays, tile,
                      "From the " + std::string(portName(port)) +
                          " side of this tile the track branches into more ways than are followed (" +
                          std::to_string(ways.size() - waysAtStart_) +
                          " found); add contacts between the turnouts so that it splits into blocks.");
}

// Follows the track from a port: on without recursion while it does not branch, one call per leg where a
// turnout branches; every step taken is undone before returning.
void WaySearch::explore(TileId tile, Port exit) {
    std::size_t taken = 0;
    while (!exhausted()) {
        const Joint joint = joints_.beyond(tile, exit);
        if (joint.kind != Beyond::Track)
            break;
        if (const std::optional<PieceSide> end = ends_.find(joint.tile, joint.port)) {
            record(*end);
            break;
        }
        const std::vector<std::uint8_t> legs = legsInto(joint.tile, joint.port);
        if (legs.size() != 1) {
            for (const std::uint8_t leg : legs)
                if (enter(joint.tile, leg, joint.port)) {
                    explore(joint.tile, path_.back().exit);
                    leave();
                }
            break;
        }
        if (!enter(joint.tile, legs.front(), joint.port))
            break;
        ++taken;
        tile = joint.tile;
        exit = path_.back().exit;
    }
    for (; taken > 0; --taken)
        leave();
}

std::vector<std::uint8_t> WaySearch::legsInto(TileId tile, Port entry) const {
    std::vector<std::uint8_t> legs;
    const auto all = tiles_.tile(tile).shape.legs();
    for (std::uint8_t i = 0; i < all.size(); ++i)
        if (all[i].touches(entry) && !((onPath_[tile] >> i) & 1U))
            legs.push_back(i);
    return legs;
}

bool WaySearch::enter(TileId id, std::uint8_t legIndex, Port entry) {
    const Tile& tile = tiles_.tile(id);
    const Leg& leg = tile.shape.legs()[legIndex];
    Undo undo;
    if (tile.role() == TileRole::Turnout) {
        if (!narrow(tile, id, leg, undo))
            return false;
        undo.turnout = true;
        turnouts_.push_back(
            {id, tile.accessory, tile.shape.turnout, 0, leg.positions, legsTouching(tile, entry) > 1});
    }
    const TrackStep step = stepThrough(tiles_, id, legIndex, entry);
    if (tile.role() == TileRole::Crossing) {
        undo.crossing = true;
        crossings_.push_back(id);
    }
    if (tile.role() == TileRole::Signal) {
        undo.signal = true;
        signals_.push_back({id,
                            tile.accessory,
                            {},
                            End::B,
                            entry == tile.shape.signalApproach,
                            distanceMm_ + step.lengthMm / 2});
    }
    onPath_[id] = std::uint8_t(onPath_[id] | (1U << legIndex));
    path_.push_back(step);
    undo_.push_back(undo);
    distanceMm_ += step.lengthMm;
    ++steps_;
    return true;
}

// Narrows the positions the turnout's article may take on this way; false when none is left (the way
// needs one article in two positions: two drawings of one turnout, or two turnouts on one address).
bool WaySearch::narrow(const Tile& tile, TileId id, const Leg& leg, Undo& undo) {
    const std::int64_t key = switchKey(tile, id);
    const auto found =
        std::find_if(masks_.begin(), masks_.end(), [key](const auto& m) { return m.first == key; });
    if (found == masks_.end()) {
        masks_.push_back({key, leg.positions});
        undo.newMask = true;
        return true;
    }
    const auto narrowed = std::uint8_t(found->second & leg.positions);
    if (narrowed == 0) {
        problems_.add(
            ProblemKind::TurnoutClash, id,
            "A way over this tile needs " +
                (key >= 0 ? "turnout " + std::to_string(key) : std::string("this turnout")) +
                " in two positions at once (it is drawn more than once, or passed twice), so that way "
                "is left out; give the drawings their own articles if they are separate turnouts.");
        return false;
    }
    undo.maskIndex = std::size_t(found - masks_.begin());
    undo.previousMask = found->second;
    found->second = narrowed;
    return true;
}

void WaySearch::leave() {
    const Undo undo = undo_.back();
    const TrackStep step = path_.back();
    undo_.pop_back();
    path_.pop_back();
    distanceMm_ -= step.lengthMm;
    onPath_[step.tile] = std::uint8_t(onPath_[step.tile] & ~(1U << step.leg));
    if (undo.turnout)
        turnouts_.pop_back();
    if (undo.crossing)
        crossings_.pop_back();
    if (undo.signal)
        signals_.pop_back();
    if (undo.newMask)
        masks_.pop_back();
    else if (undo.maskIndex)
        masks_[*undo.maskIndex].second = undo.previousMask;
}

void WaySearch::record(PieceSide to) {
    RawWay way{start_, to, path_, turnouts_, crossings_, signals_};
    for (TurnoutOnWay& turnout : way.turnouts) {
        const std::int64_t key = switchKey(tiles_.tile(turnout.tile), turnout.tile);
        const auto mask =
            std::find_if(masks_.begin(), masks_.end(), [key](const auto& m) { return m.first == key; });
        turnout.position = std::countr_zero(unsigned(mask->second));
    }
    ways_->push_back(std::move(way));
}

} // namespace stellwerk::trackgraph
