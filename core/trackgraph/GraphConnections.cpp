// The connections of GraphAssembly: the ways between piece ends turned into connections between block
// ends (one per way and turnout settings, whichever drawing it was found on), the routes of
// fahrstrassen.cs2 checked against them, and which connections cannot be set at the same time.
#include "trackgraph/GraphAssembly.h"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

namespace stellwerk::trackgraph {

namespace {

using Settings = std::vector<std::pair<std::int64_t, int>>;

// The turnouts of a way by article (or a key of the tile's own when it names none) and position.
Settings settingsOf(const RawWay& way) {
    Settings settings;
    for (const TurnoutOnWay& turnout : way.turnouts)
        settings.push_back(
            {turnout.article ? *turnout.article : -1 - std::int64_t(turnout.tile), turnout.position});
    return settings;
}

bool sets(const Connection& connection, const std::map<std::int64_t, int>& settings) {
    if (connection.turnouts.empty())
        return false;
    return std::all_of(connection.turnouts.begin(), connection.turnouts.end(),
                       [&](const TurnoutOnWay& turnout) {
                           if (!turnout.article)
                               return false;
                           const auto setting = settings.find(*turnout.article);
                           return setting != settings.end() && setting->second >= 0 && setting->second < 8 &&
                                  ((turnout.legMask >> setting->second) & 1U);
                       });
}

void addPairs(std::vector<std::vector<int>>& conflicts, const std::vector<int>& together) {
    for (std::size_t i = 0; i < together.size(); ++i)
        for (std::size_t j = i + 1; j < together.size(); ++j)
            if (together[i] != together[j]) {
                conflicts[std::size_t(together[i])].push_back(together[j] + 1);
                conflicts[std::size_t(together[j])].push_back(together[i] + 1);
            }
}

} // namespace

void GraphAssembly::buildConnections() {
    struct Candidate {
        BlockEnd from;
        BlockEnd to;
        Settings settings;
        bool copy; // found on a drawing other than the block's first
        std::uint32_t way;
    };
    std::vector<Candidate> candidates;
    for (std::uint32_t w = 0; w < ways_.size(); ++w) {
        const RawWay& way = ways_[w];
        const bool copy = piecesOfBlock_[blockOfPiece_[way.from.piece]].front() != way.from.piece;
        candidates.push_back({blockEndOf(way.from), blockEndOf(way.to), settingsOf(way), copy, w});
    }
    const auto key = [](const Candidate& c) { return std::tie(c.from, c.to, c.settings); };
    std::sort(candidates.begin(), candidates.end(), [&key](const Candidate& a, const Candidate& b) {
        return std::tuple(key(a), a.copy, a.way) < std::tuple(key(b), b.copy, b.way);
    });
    candidates.erase(std::unique(candidates.begin(), candidates.end(),
                                 [&key](const Candidate& a, const Candidate& b) { return key(a) == key(b); }),
                     candidates.end());
    for (const Candidate& candidate : candidates) {
        Connection connection = connectionOf(ways_[candidate.way]);
        connection.id = int(graph_.connections_.size() + 1);
        connection.from = candidate.from;
        connection.to = candidate.to;
        graph_.connections_.push_back(std::move(connection));
    }
}

Connection GraphAssembly::connectionOf(const RawWay& way) const {
    const BlockNaming naming(graph_.tiles_, source_.accessories, source_.routes);
    Connection connection;
    connection.path = way.path;
    connection.turnouts = way.turnouts;
    connection.crossings = way.crossings;
    connection.signalsAlong = way.signalsAlong;
    for (SignalOnTrack& signal : connection.signalsAlong)
        signal.name = naming.signalName(graph_.tiles_.tile(signal.tile));
    for (const TrackStep& step : way.path)
        connection.lengthMm += step.lengthMm;
    return connection;
}

// A turnout drawn on several pages is one turnout: each drawing must join the same blocks in the same
// positions. Compared with the drawing first in plan order; drawings on one page are separate turnouts
// that share an address (a crossover), not drawings of one.
void GraphAssembly::checkTurnoutDrawings() {
    std::map<TileId, std::set<std::tuple<int, int, int>>> joins; // turnout tile -> (block, block, position)
    for (const RawWay& way : ways_)
        for (const TurnoutOnWay& turnout : way.turnouts) {
            const int from = int(blockOfPiece_[way.from.piece]) + 1;
            const int to = int(blockOfPiece_[way.to.piece]) + 1;
            joins[turnout.tile].insert({std::min(from, to), std::max(from, to), turnout.position});
        }
    std::map<std::int64_t, TileId> first;
    const TrackTiles& tiles = graph_.tiles_;
    for (TileId id = 0; id < tiles.size(); ++id) {
        const Tile& tile = tiles.tile(id);
        if (tile.role() != TileRole::Turnout || !tile.accessory)
            continue;
        const auto [reference, fresh] = first.emplace(*tile.accessory, id);
        if (!fresh && tiles.tile(reference->second).page != tile.page &&
            joins[id] != joins[reference->second])
            problems_.add(ProblemKind::DrawingsDisagree, id,
                          "Turnout " + std::to_string(*tile.accessory) + " is also drawn at " +
                              describePlace(tiles, reference->second) + ", and the drawings differ: here " +
                              describeJoins(joins[id], tile.shape.turnout) + ", there " +
                              describeJoins(joins[reference->second], tile.shape.turnout) +
                              "; make the pages agree.");
    }
}

std::string GraphAssembly::describeJoins(const std::set<std::tuple<int, int, int>>& joins,
                                         TurnoutKind kind) const {
    if (joins.empty())
        return "it joins no blocks";
    std::string text;
    for (const auto& [a, b, position] : joins)
        text += std::string(text.empty() ? "" : ", ") + "'" + graph_.blocks_[std::size_t(a - 1)].name +
                "' and '" + graph_.blocks_[std::size_t(b - 1)].name + "' " +
                std::string(positionName(kind, position));
    return "it joins " + text;
}

void GraphAssembly::checkRoutes() {
    if (!source_.routes)
        return;
    std::vector<std::int64_t> turnoutArticles;
    for (const Tile& tile : graph_.tiles_.tiles())
        if (tile.role() == TileRole::Turnout && tile.accessory)
            turnoutArticles.push_back(*tile.accessory);
    std::sort(turnoutArticles.begin(), turnoutArticles.end());
    for (const cs2config::Route& route : source_.routes->routes)
        checkRoute(route, turnoutArticles);
    for (Connection& connection : graph_.connections_) {
        std::sort(connection.routes.begin(), connection.routes.end());
        connection.routes.erase(std::unique(connection.routes.begin(), connection.routes.end()),
                                connection.routes.end());
    }
}

// A route names every connection whose turnouts it all sets as the connection needs; a route that sets
// turnouts of the plan but names none is reported.
void GraphAssembly::checkRoute(const cs2config::Route& route,
                               const std::vector<std::int64_t>& turnoutArticles) {
    std::map<std::int64_t, int> settings;
    for (const cs2config::RouteStep& step : route.steps)
        if (!step.runsRoute() && (step.type.empty() || step.type == cs2config::RouteStep::accessoryType) &&
            std::binary_search(turnoutArticles.begin(), turnoutArticles.end(), step.accessory))
            settings[step.accessory] = int(std::clamp<std::int64_t>(step.position, -1, 255));
    if (settings.empty())
        return;
    bool named = false;
    for (Connection& connection : graph_.connections_)
        if (sets(connection, settings)) {
            connection.routes.push_back(route.id);
            named = true;
        }
    if (!named)
        reportRoute(route, settings);
}

// At the route's button on the plan, else at its first turnout.
void GraphAssembly::reportRoute(const cs2config::Route& route, const std::map<std::int64_t, int>& settings) {
    const TrackTiles& tiles = graph_.tiles_;
    std::optional<TileId> place;
    for (TileId id = 0; id < tiles.size() && !place; ++id)
        if (tiles.tile(id).type == "fahrstrasse" && tiles.tile(id).article == route.id)
            place = id;
    std::string turnouts;
    for (const auto& [article, position] : settings) {
        TileId id = 0;
        while (tiles.tile(id).role() != TileRole::Turnout || tiles.tile(id).accessory != article)
            ++id; // there is one: only the plan's turnouts are in `settings`
        place = place ? place : id;
        const TurnoutKind kind = tiles.tile(id).shape.turnout;
        const bool known = position >= 0 && position < positionCount(kind);
        turnouts += (turnouts.empty() ? "turnout " : ", turnout ") + std::to_string(article) +
                    (known ? " " + std::string(positionName(kind, position))
                           : " to position " + std::to_string(position));
    }
    problems_.add(
        ProblemKind::RouteNoConnection, *place,
        "Route '" + route.name + "' (" + std::to_string(route.id) + ") sets " + turnouts +
            ", which together lead from no block to another as the plan draws them; check the route's "
            "turnouts against the plan.");
}

// Connections conflict when they share a tile (a crossing, a turnout, track between blocks) or need one
// turnout article in different positions.
void GraphAssembly::findConflicts() {
    std::vector<std::pair<TileId, int>> onTile;
    std::vector<std::tuple<std::int64_t, int, int>> onArticle;
    const std::vector<Connection>& connections = graph_.connections_;
    for (std::size_t c = 0; c < connections.size(); ++c) {
        for (const TrackStep& step : connections[c].path)
            onTile.push_back({step.tile, int(c)});
        for (const TurnoutOnWay& turnout : connections[c].turnouts)
            if (turnout.article)
                onArticle.push_back({*turnout.article, turnout.position, int(c)});
    }
    std::sort(onTile.begin(), onTile.end());
    onTile.erase(std::unique(onTile.begin(), onTile.end()), onTile.end());
    std::sort(onArticle.begin(), onArticle.end());
    std::vector<std::vector<int>> conflicts(connections.size());
    for (std::size_t i = 0; i < onTile.size();) {
        std::vector<int> together;
        const TileId tile = onTile[i].first;
        for (; i < onTile.size() && onTile[i].first == tile; ++i)
            together.push_back(onTile[i].second);
        addPairs(conflicts, together);
    }
    for (std::size_t i = 0; i < onArticle.size(); ++i)
        for (std::size_t j = i + 1;
             j < onArticle.size() && std::get<0>(onArticle[j]) == std::get<0>(onArticle[i]); ++j)
            if (std::get<1>(onArticle[j]) != std::get<1>(onArticle[i]))
                addPairs(conflicts, {std::get<2>(onArticle[i]), std::get<2>(onArticle[j])});
    for (std::size_t c = 0; c < connections.size(); ++c) {
        std::sort(conflicts[c].begin(), conflicts[c].end());
        conflicts[c].erase(std::unique(conflicts[c].begin(), conflicts[c].end()), conflicts[c].end());
        graph_.connections_[c].conflicts = std::move(conflicts[c]);
    }
}

} // namespace stellwerk::trackgraph
