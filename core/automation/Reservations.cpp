#include "automation/Reservations.h"

#include <algorithm>

namespace stellwerk::automation {

namespace {

std::uint32_t ownerIn(const std::map<int, std::uint32_t>& owners, int id) {
    const auto found = owners.find(id);
    return found == owners.end() ? 0 : found->second;
}

bool sharesCrossing(const trackgraph::Connection& first, const trackgraph::Connection& second) {
    return std::any_of(first.crossings.begin(), first.crossings.end(), [&](trackgraph::TileId tile) {
        return std::find(second.crossings.begin(), second.crossings.end(), tile) != second.crossings.end();
    });
}

bool sharesTurnout(const trackgraph::Connection& first, const trackgraph::Connection& second) {
    for (const trackgraph::TurnoutOnWay& mine : first.turnouts)
        for (const trackgraph::TurnoutOnWay& theirs : second.turnouts)
            if (mine.article && mine.article == theirs.article)
                return true;
    return false;
}

} // namespace

bool Reservations::reserve(std::uint32_t locId, const Path& path) {
    for (const int block : path.blocks)
        if (!blockAvailable(block, locId))
            return false;
    for (const int connection : path.connections)
        if (!connectionAvailable(connection, locId))
            return false;
    for (const int block : path.blocks)
        blocks_[block] = locId;
    for (const int connection : path.connections)
        connections_[connection] = locId;
    return true;
}

bool Reservations::holdBlock(std::uint32_t locId, int block) {
    if (!blockAvailable(block, locId))
        return false;
    blocks_[block] = locId;
    return true;
}

void Reservations::releaseBlock(std::uint32_t locId, int block) {
    if (blockOwner(block) == locId)
        blocks_.erase(block);
}

void Reservations::releaseConnection(std::uint32_t locId, int connection) {
    if (connectionOwner(connection) == locId)
        connections_.erase(connection);
}

void Reservations::releaseAllBut(std::uint32_t locId, const std::vector<int>& keepBlocks,
                                 const std::vector<int>& keepConnections) {
    const auto releasable = [locId](const std::vector<int>& keep) {
        return [locId, &keep](const auto& entry) {
            return entry.second == locId && std::find(keep.begin(), keep.end(), entry.first) == keep.end();
        };
    };
    std::erase_if(blocks_, releasable(keepBlocks));
    std::erase_if(connections_, releasable(keepConnections));
}

std::uint32_t Reservations::blockOwner(int block) const {
    return ownerIn(blocks_, block);
}

std::uint32_t Reservations::connectionOwner(int connection) const {
    return ownerIn(connections_, connection);
}

bool Reservations::blockAvailable(int block, std::uint32_t locId) const {
    const std::uint32_t owner = blockOwner(block);
    return owner == 0 || owner == locId;
}

bool Reservations::connectionAvailable(int connection, std::uint32_t locId) const {
    const std::uint32_t owner = connectionOwner(connection);
    if (owner != 0)
        return owner == locId;
    return !conflictsWithOthers(graph_.connection(connection), locId);
}

// Another train's connection shares a tile, a turnout or a crossing with this one.
bool Reservations::conflictsWithOthers(const trackgraph::Connection& connection, std::uint32_t locId) const {
    for (const auto& [id, owner] : connections_) {
        if (owner == locId)
            continue;
        const trackgraph::Connection& theirs = graph_.connection(id);
        if (std::find(connection.conflicts.begin(), connection.conflicts.end(), id) !=
                connection.conflicts.end() ||
            sharesTurnout(connection, theirs) || sharesCrossing(connection, theirs))
            return true;
    }
    return false;
}

std::optional<std::pair<std::uint32_t, int>> Reservations::turnoutOwner(std::int64_t article) const {
    for (const auto& [id, owner] : connections_)
        for (const trackgraph::TurnoutOnWay& turnout : graph_.connection(id).turnouts)
            if (turnout.article == article)
                return std::make_pair(owner, turnout.position);
    return std::nullopt;
}

std::vector<int> Reservations::blocksOf(std::uint32_t locId) const {
    std::vector<int> held;
    for (const auto& [block, owner] : blocks_)
        if (owner == locId)
            held.push_back(block);
    return held;
}

std::vector<int> Reservations::connectionsOf(std::uint32_t locId) const {
    std::vector<int> held;
    for (const auto& [connection, owner] : connections_)
        if (owner == locId)
            held.push_back(connection);
    return held;
}

} // namespace stellwerk::automation
