#include "trackgraph/TrackGraph.h"

#include "trackgraph/GraphAssembly.h"
#include "trackgraph/TrackJoints.h"

#include <algorithm>

namespace stellwerk::trackgraph {

namespace {

LeadKind leadKindOf(Beyond beyond) {
    switch (beyond) {
    case Beyond::BufferStop:
        return LeadKind::BufferStop;
    case Beyond::Turntable:
        return LeadKind::Turntable;
    case Beyond::Track:
    case Beyond::OpenEnd:
        break;
    }
    return LeadKind::OpenEnd;
}

// The leg a train entering a tile through `entry` takes with the turnouts as they stand; nullopt when a
// turnout stops it (the lead says why). Where a two-drive slip sets two legs from one side, the straight.
std::optional<std::uint8_t> legToTake(const Tile& tile, TileId id, Port entry, const PositionOf& positionOf,
                                      Lead& lead) {
    const auto legs = tile.shape.legs();
    lead.facing =
        std::count_if(legs.begin(), legs.end(), [entry](const Leg& leg) { return leg.touches(entry); }) > 1;
    std::optional<int> position;
    if (tile.role() == TileRole::Turnout) {
        position = tile.accessory && positionOf ? positionOf(*tile.accessory) : std::nullopt;
        if (!position) {
            lead.kind = LeadKind::NotSet;
            lead.turnout = id;
            lead.article = tile.accessory;
            return std::nullopt;
        }
    }
    std::optional<std::uint8_t> taken;
    for (std::uint8_t i = 0; i < legs.size(); ++i) {
        if (!legs[i].touches(entry) || (position && !legs[i].setIn(*position)))
            continue;
        if (!taken || legs[i].lengthMm() == StraightTileMm)
            taken = i;
    }
    if (!taken) {
        lead.kind = LeadKind::SetAgainst;
        lead.turnout = id;
        lead.article = tile.accessory;
    }
    return taken;
}

} // namespace

std::string_view endName(End end) {
    return end == End::A ? "a" : "b";
}

std::string_view endKindName(EndKind kind) {
    switch (kind) {
    case EndKind::Junction:
        return "junction";
    case EndKind::Block:
        return "block";
    case EndKind::BufferStop:
        return "buffer stop";
    case EndKind::Turntable:
        return "turntable";
    case EndKind::OpenEnd:
        break;
    }
    return "open end";
}

GraphSource GraphSource::of(const cs2config::TrackLayout& layout, const cs2config::AccessoryFile* accessories,
                            const cs2config::RouteFile* routes) {
    GraphSource source;
    for (const cs2config::TrackLayoutPage& page : layout.pages)
        source.pages.push_back({page.id, page.name, page.loaded ? &page.page.elements : nullptr});
    source.accessories = accessories;
    source.routes = routes;
    return source;
}

TrackGraph TrackGraph::derive(const GraphSource& source) {
    return GraphAssembly(source).run();
}

TrackGraph TrackGraph::derive(const cs2config::TrackLayout& layout,
                              const cs2config::AccessoryFile* accessories,
                              const cs2config::RouteFile* routes) {
    return derive(GraphSource::of(layout, accessories, routes));
}

std::vector<int> TrackGraph::blocksAt(TileId tile) const {
    std::vector<int> blocks;
    if (tile < tileBlocks_.size())
        for (const int block : tileBlocks_[tile])
            if (block != 0)
                blocks.push_back(block);
    return blocks;
}

std::optional<TileId> TrackGraph::tileAt(const TilePlace& place) const {
    const std::optional<std::uint32_t> page = tiles_.pageWithId(place.page);
    return page ? tiles_.at(*page, place.column, place.row) : std::nullopt;
}

std::optional<int> TrackGraph::blockWithContact(const ContactKey& contact) const {
    for (const Block& block : blocks_)
        for (const ContactOnBlock& on : block.contacts)
            if (on.contact == contact)
                return block.id;
    return std::nullopt;
}

std::vector<int> TrackGraph::connectionsFrom(const BlockEnd& end) const {
    std::vector<int> found;
    for (const Connection& connection : connections_)
        if (connection.from == end)
            found.push_back(connection.id);
    return found;
}

std::vector<const Problem*> TrackGraph::problemsAt(TileId tile) const {
    std::vector<const Problem*> found;
    for (const Problem& problem : problems_)
        if (problem.tile == tile)
            found.push_back(&problem);
    return found;
}

std::optional<BlockEnd> TrackGraph::blockEndAt(TileId tile, Port port) const {
    const std::uint32_t key = (tile << 4) | std::uint32_t(port);
    const auto found = std::lower_bound(endIndex_.begin(), endIndex_.end(), key,
                                        [](const auto& entry, std::uint32_t k) { return entry.first < k; });
    if (found == endIndex_.end() || found->first != key)
        return std::nullopt;
    return found->second;
}

Lead TrackGraph::follow(const BlockEnd& from, const PositionOf& positionOf) const {
    if (from.block < 1 || from.block > int(blocks_.size()))
        return {};
    const BlockEndInfo& start = block(from.block).end(from.end);
    return followFrom(start.tile, start.port, positionOf);
}

Lead TrackGraph::followFrom(TileId tile, Port exit, const PositionOf& positionOf) const {
    const TrackJoints joints(tiles_, links_);
    Lead lead;
    for (std::size_t steps = 0; steps <= 4 * tiles_.size(); ++steps) {
        const Joint joint = joints.beyond(tile, exit);
        if (joint.kind != Beyond::Track) {
            lead.kind = leadKindOf(joint.kind);
            return lead;
        }
        if (const std::optional<BlockEnd> reached = blockEndAt(joint.tile, joint.port)) {
            lead.kind = LeadKind::Block;
            lead.reached = *reached;
            return lead;
        }
        const std::optional<std::uint8_t> leg =
            legToTake(tiles_.tile(joint.tile), joint.tile, joint.port, positionOf, lead);
        if (!leg)
            return lead;
        lead.path.push_back(stepThrough(tiles_, joint.tile, *leg, joint.port));
        tile = joint.tile;
        exit = lead.path.back().exit;
    }
    lead.kind = LeadKind::TooLong;
    return lead;
}

} // namespace stellwerk::trackgraph
