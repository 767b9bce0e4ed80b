#pragma once

#include "automation/Path.h"
#include "trackgraph/TrackGraph.h"

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace stellwerk::automation {

// Who owns which piece of track: every block and connection (with its turnouts and crossings, and so every
// connection that conflicts with it) belongs to at most one train. A way is reserved whole or not at all,
// and given back piece by piece behind the train, never ahead of it.
class Reservations {
public:
    explicit Reservations(const trackgraph::TrackGraph& graph) : graph_(graph) {}

    // Reserves every block and connection of the way for the train; false (nothing reserved) when any of
    // them is another train's.
    bool reserve(std::uint32_t locId, const Path& path);
    // The block a train was placed in.
    bool holdBlock(std::uint32_t locId, int block);
    void releaseBlock(std::uint32_t locId, int block);
    void releaseConnection(std::uint32_t locId, int connection);
    // Everything the train holds except the blocks and connections in `keepBlocks` and `keepConnections`.
    void releaseAllBut(std::uint32_t locId, const std::vector<int>& keepBlocks,
                       const std::vector<int>& keepConnections);

    // 0: nobody.
    std::uint32_t blockOwner(int block) const;
    std::uint32_t connectionOwner(int connection) const;
    // Whether the train may have the block or connection: free, or its own.
    bool blockAvailable(int block, std::uint32_t locId) const;
    bool connectionAvailable(int connection, std::uint32_t locId) const;
    // The train that owns a turnout and the position its way needs; nullopt when no way passes it.
    std::optional<std::pair<std::uint32_t, int>> turnoutOwner(std::int64_t article) const;
    std::vector<int> blocksOf(std::uint32_t locId) const;
    std::vector<int> connectionsOf(std::uint32_t locId) const;

private:
    bool conflictsWithOthers(const trackgraph::Connection& connection, std::uint32_t locId) const;

    const trackgraph::TrackGraph& graph_;
    std::map<int, std::uint32_t> blocks_;
    std::map<int, std::uint32_t> connections_;
};

} // namespace stellwerk::automation
