#include "trackgraph/Stretches.h"

#include <algorithm>
#include <set>
#include <tuple>

namespace stellwerk::trackgraph {

namespace {

bool isVisited(const std::vector<std::uint8_t>& visited, TileId tile, std::uint8_t leg) {
    return (visited[tile] >> leg) & 1U;
}

void markVisited(std::vector<std::uint8_t>& visited, TileId tile, std::uint8_t leg) {
    visited[tile] = std::uint8_t(visited[tile] | (1U << leg));
}

std::optional<std::uint8_t> legAt(const Tile& tile, Port port) {
    const auto legs = tile.shape.legs();
    for (std::uint8_t i = 0; i < legs.size(); ++i)
        if (legs[i].touches(port))
            return i;
    return std::nullopt;
}

TrackStep reversed(TrackStep step) {
    std::swap(step.entry, step.exit);
    return step;
}

StretchEndKind endKind(Beyond beyond) {
    switch (beyond) {
    case Beyond::BufferStop:
        return StretchEndKind::BufferStop;
    case Beyond::Turntable:
        return StretchEndKind::Turntable;
    case Beyond::Track:
    case Beyond::OpenEnd:
        break;
    }
    return StretchEndKind::OpenEnd;
}

std::string turnoutName(const Tile& tile) {
    return tile.accessory ? "Turnout " + std::to_string(*tile.accessory) : "This turnout";
}

} // namespace

TrackStep stepThrough(const TrackTiles& tiles, TileId tile, std::uint8_t leg, Port entry) {
    const Leg& piece = tiles.tile(tile).shape.legs()[leg];
    return {tile, leg, entry, piece.otherEnd(entry), piece.lengthMm()};
}

Stretches::Stretches(const TrackJoints& joints)
    : joints_(joints), tiles_(joints.tiles()), isolated_(joints.tiles().size(), false),
      indicators_(joints.tiles().size(), false) {
    for (TileId id = 0; id < tiles_.size(); ++id) {
        const Tile& tile = tiles_.tile(id);
        bool joined = false;
        for (const Leg& leg : tile.shape.legs())
            for (const Port port : {leg.from, leg.to})
                joined = joined || (port != Port::End && joints_.beyond(id, port).kind == Beyond::Track);
        isolated_[id] = tile.shape.isTrack() && !joined;
    }
    leaveOutIndicatorPages();
}

// A page whose track is nothing but contact tiles is an S88 display (rows of indicators), not track.
void Stretches::leaveOutIndicatorPages() {
    for (TileId first = 0; first < tiles_.size();) {
        const std::uint32_t page = tiles_.tile(first).page;
        TileId end = first;
        bool contacts = false;
        bool otherTrack = false;
        for (; end < tiles_.size() && tiles_.tile(end).page == page; ++end) {
            const Tile& tile = tiles_.tile(end);
            contacts = contacts || tile.role() == TileRole::Contact;
            otherTrack = otherTrack || (tile.shape.isTrack() && tile.role() != TileRole::Contact);
        }
        for (TileId id = first; id < end && contacts && !otherTrack; ++id)
            indicators_[id] = true;
        first = end;
    }
}

std::vector<Stretch> Stretches::trace() const {
    std::vector<std::uint8_t> visited(tiles_.size(), 0);
    std::vector<Stretch> stretches;
    for (TileId id = 0; id < tiles_.size(); ++id) {
        const Tile& tile = tiles_.tile(id);
        if (isolated_[id] || indicators_[id] || tile.shape.isJunction())
            continue;
        for (std::uint8_t leg = 0; leg < tile.shape.legCount; ++leg)
            if (!isVisited(visited, id, leg))
                stretches.push_back(traceFrom(id, leg, visited));
    }
    return stretches;
}

Stretch Stretches::traceFrom(TileId tile, std::uint8_t leg, std::vector<std::uint8_t>& visited) const {
    markVisited(visited, tile, leg);
    const TrackStep start = stepThrough(tiles_, tile, leg, tiles_.tile(tile).shape.legs()[leg].from);
    Stretch stretch;
    std::vector<TrackStep> ahead;
    if (!extend(start, ahead, stretch.last, start, visited)) {
        stretch.loop = true;
        stretch.steps.push_back(start);
        stretch.steps.insert(stretch.steps.end(), ahead.begin(), ahead.end());
        return stretch;
    }
    std::vector<TrackStep> behind;
    extend(reversed(start), behind, stretch.first, start, visited);
    for (auto it = behind.rbegin(); it != behind.rend(); ++it)
        stretch.steps.push_back(reversed(*it));
    stretch.steps.push_back(start);
    stretch.steps.insert(stretch.steps.end(), ahead.begin(), ahead.end());
    inPlanOrder(stretch);
    return stretch;
}

// Turns a stretch so that it runs from its end whose tile (then port) comes first in plan order, so that
// what is cut from it does not depend on the tile the tracing began at.
void Stretches::inPlanOrder(Stretch& stretch) {
    const TrackStep& first = stretch.steps.front();
    const TrackStep& last = stretch.steps.back();
    if (std::tuple(first.tile, first.entry) <= std::tuple(last.tile, last.exit))
        return;
    std::reverse(stretch.steps.begin(), stretch.steps.end());
    for (TrackStep& step : stretch.steps)
        std::swap(step.entry, step.exit);
    std::swap(stretch.first, stretch.last);
}

bool Stretches::extend(TrackStep from, std::vector<TrackStep>& steps, StretchEnd& end, const TrackStep& start,
                       std::vector<std::uint8_t>& visited) const {
    for (TrackStep current = from;;) {
        const Joint joint = joints_.beyond(current.tile, current.exit);
        if (joint.kind != Beyond::Track) {
            end = {endKind(joint.kind)};
            return true;
        }
        const Tile& next = tiles_.tile(joint.tile);
        if (next.shape.isJunction()) {
            end = {StretchEndKind::Junction, joint.tile, joint.port};
            return true;
        }
        const std::optional<std::uint8_t> leg = legAt(next, joint.port);
        if (joint.tile == start.tile && leg == start.leg)
            return false;
        if (!leg || isVisited(visited, joint.tile, *leg)) { // cannot happen on well-formed legs
            end = {};
            return true;
        }
        markVisited(visited, joint.tile, *leg);
        current = stepThrough(tiles_, joint.tile, *leg, joint.port);
        steps.push_back(current);
    }
}

void Stretches::reportLooseEnds(ProblemList& problems) const {
    reportIsolated(problems);
    for (TileId id = 0; id < tiles_.size(); ++id)
        if (!isolated_[id] && !indicators_[id] && tiles_.tile(id).shape.isTrack())
            reportTile(id, problems);
}

void Stretches::reportTile(TileId id, ProblemList& problems) const {
    const Tile& tile = tiles_.tile(id);
    std::set<Port> seen;
    for (const Leg& leg : tile.shape.legs())
        for (const Port port : {leg.from, leg.to}) {
            if (!isGeometric(port) || !seen.insert(port).second ||
                joints_.beyond(id, port).kind == Beyond::Track)
                continue;
            const std::string side(portName(port));
            if (tile.role() == TileRole::Turnout) {
                problems.add(ProblemKind::TurnoutLegNowhere, id,
                             turnoutName(tile) + " has no track at its " + side +
                                 " side, so the way through it there leads nowhere; add the track or a "
                                 "buffer stop.");
            } else if (const std::optional<TileId> other = tiles_.beside(id, port)) {
                const TilePlace& place = tiles_.tile(*other).place;
                problems.add(ProblemKind::OpenEnd, id,
                             "The track at the " + side +
                                 " side does not meet the track of the tile beside it "
                                 "(column " +
                                 std::to_string(place.column) + ", row " + std::to_string(place.row) +
                                 "); turn one of them or add a buffer stop.");
            } else {
                problems.add(ProblemKind::OpenEnd, id,
                             "The track ends at the " + side +
                                 " side without a buffer stop; add the missing track or a buffer stop.");
            }
        }
}

void Stretches::reportIsolated(ProblemList& problems) const {
    // Tiles are ordered by page: each page's tiles follow each other.
    for (TileId first = 0; first < tiles_.size();) {
        const std::uint32_t page = tiles_.tile(first).page;
        std::vector<TileId> alone;
        bool joinedTrack = false;
        TileId id = first;
        for (; id < tiles_.size() && tiles_.tile(id).page == page; ++id) {
            joinedTrack = joinedTrack || (tiles_.tile(id).shape.isTrack() && !isolated_[id]);
            // Arrows may be plain buttons for changing pages; indicator pages are not track.
            if (isolated_[id] && !indicators_[id] && tiles_.tile(id).role() != TileRole::PageLink)
                alone.push_back(id);
        }
        first = id;
        reportAlone(page, alone, joinedTrack, problems);
    }
}

void Stretches::reportAlone(std::uint32_t page, const std::vector<TileId>& alone, bool joinedTrack,
                            ProblemList& problems) const {
    if (alone.empty())
        return;
    if (!joinedTrack) {
        problems.add(ProblemKind::JoinsNothing, alone.front(),
                     "No track on page " + describePage(tiles_.pages()[page]) + " joins another tile (" +
                         std::to_string(alone.size()) +
                         " tiles stand alone); the page is left out of the graph.");
        return;
    }
    for (const TileId id : alone)
        problems.add(ProblemKind::JoinsNothing, id,
                     "This " + tiles_.tile(id).type +
                         " tile joins no other track; move it onto the track or remove it.");
}

} // namespace stellwerk::trackgraph
