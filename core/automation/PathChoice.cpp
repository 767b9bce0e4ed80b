#include "automation/PathChoice.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <deque>
#include <set>

namespace stellwerk::automation {

using trackgraph::BlockEnd;
using trackgraph::End;

namespace {

// A way being searched: its connections so far and the end it leaves the last block through.
struct Partial {
    BlockEnd exit;
    std::vector<int> connections;
    std::vector<int> blocks;
};

std::string lowered(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

Path pathOf(const trackgraph::TrackGraph& graph, const Partial& partial) {
    Path path{partial.connections, partial.blocks, {}};
    for (const int id : partial.connections)
        for (const trackgraph::TurnoutOnWay& turnout : graph.connection(id).turnouts)
            path.turnouts.emplace_back(*turnout.article, turnout.position);
    return path;
}

} // namespace

std::optional<Path> PathChoice::choose(const BlockEnd& front, int trainLengthMm,
                                       const TrackState& state) const {
    std::deque<Partial> open{Partial{front, {}, {}}};
    std::set<BlockEnd> seen{front};
    std::optional<Partial> plain;
    while (!open.empty()) {
        const Partial partial = std::move(open.front());
        open.pop_front();
        if (int(partial.blocks.size()) >= MaxBlocks)
            continue;
        for (const int id : graph_.connectionsFrom(partial.exit)) {
            const trackgraph::Connection& connection = graph_.connection(id);
            const BlockEnd exit{connection.to.block, trackgraph::otherEnd(connection.to.end)};
            if (!usable(connection, state) || !state.blockFree(exit.block) || !seen.insert(exit).second)
                continue;
            Partial next{exit, partial.connections, partial.blocks};
            next.connections.push_back(id);
            next.blocks.push_back(exit.block);
            if (canStop(exit.block, exit.end, trainLengthMm, state)) {
                if (isStation(exit.block, exit.end))
                    return pathOf(graph_, next);
                if (!plain)
                    plain = next;
            }
            open.push_back(std::move(next));
        }
    }
    if (plain)
        return pathOf(graph_, *plain);
    return std::nullopt;
}

std::optional<Path> PathChoice::chooseTo(const BlockEnd& front, int target, int trainLengthMm,
                                         const TrackState& state) const {
    if (target <= 0 || target > int(graph_.blocks().size()) || graph_.block(target).lengthMm < trainLengthMm)
        return std::nullopt;
    if (std::optional<Path> whole = routeTo(front, target, &state))
        return whole;
    // Not free all the way now: as far along the shortest route as is free, to a block it may stop in.
    const std::optional<Path> route = routeTo(front, target, nullptr);
    if (!route)
        return std::nullopt;
    std::size_t stretch = 0;
    for (std::size_t i = 0; i < route->blocks.size(); ++i) {
        const trackgraph::Connection& connection = graph_.connection(route->connections[i]);
        if (!state.connectionFree(connection.id) || !state.blockFree(route->blocks[i]))
            break;
        if (canStop(route->blocks[i], trackgraph::otherEnd(connection.to.end), trainLengthMm, state))
            stretch = i + 1;
    }
    if (stretch == 0)
        return std::nullopt;
    const auto upTo = [stretch](const std::vector<int>& all) {
        return std::vector<int>(all.begin(), all.begin() + std::ptrdiff_t(stretch));
    };
    return pathOf(graph_, Partial{front, upTo(route->connections), upTo(route->blocks)});
}

// Breadth first to the target block: over free track only when `state` is given, else over any track with
// switchable turnouts (the route as the plan has it).
std::optional<Path> PathChoice::routeTo(const BlockEnd& front, int target, const TrackState* state) const {
    const auto switchable = [](const trackgraph::Connection& connection) {
        return std::all_of(
            connection.turnouts.begin(), connection.turnouts.end(),
            [](const trackgraph::TurnoutOnWay& turnout) { return turnout.article.has_value(); });
    };
    std::deque<Partial> open{Partial{front, {}, {}}};
    std::set<BlockEnd> seen{front};
    while (!open.empty()) {
        const Partial partial = std::move(open.front());
        open.pop_front();
        for (const int id : graph_.connectionsFrom(partial.exit)) {
            const trackgraph::Connection& connection = graph_.connection(id);
            const BlockEnd exit{connection.to.block, trackgraph::otherEnd(connection.to.end)};
            if (!switchable(connection) ||
                (state && (!usable(connection, *state) || !state->blockFree(exit.block))) ||
                !seen.insert(exit).second)
                continue;
            Partial next{exit, partial.connections, partial.blocks};
            next.connections.push_back(id);
            next.blocks.push_back(exit.block);
            if (exit.block == target)
                return pathOf(graph_, next);
            open.push_back(std::move(next));
        }
    }
    return std::nullopt;
}

bool PathChoice::usable(const trackgraph::Connection& connection, const TrackState& state) const {
    return state.connectionFree(connection.id) &&
           std::all_of(connection.turnouts.begin(), connection.turnouts.end(),
                       [](const trackgraph::TurnoutOnWay& turnout) { return turnout.article.has_value(); });
}

bool PathChoice::canStop(int block, End towards, int trainLengthMm, const TrackState& state) const {
    return graph_.block(block).lengthMm >= trainLengthMm && hasWayOn(block, towards, state) &&
           clearAhead({block, towards}, state);
}

// Along the single line ahead (ways into sidings that end at buffer stops do not count) up to the next
// place where trains can pass: no train standing there or bound there the other way.
bool PathChoice::clearAhead(const BlockEnd& from, const TrackState& state) const {
    if (!state.travelling)
        return true;
    BlockEnd at = from;
    for (std::size_t steps = 0; steps < graph_.blocks().size(); ++steps) {
        std::vector<int> onward;
        for (const int id : graph_.connectionsFrom(at)) {
            const trackgraph::Connection& connection = graph_.connection(id);
            if (!graph_.connectionsFrom({connection.to.block, trackgraph::otherEnd(connection.to.end)})
                     .empty())
                onward.push_back(id);
        }
        if (onward.size() != 1)
            return true; // a place to pass, or the end of the line
        const trackgraph::Connection& line = graph_.connection(onward.front());
        const End travel = trackgraph::otherEnd(line.to.end);
        if (const std::optional<End> other = state.travelling(line.to.block); other && *other != travel)
            return false;
        at = {line.to.block, travel};
        if (at == from)
            return true; // round a loop without a place to pass
    }
    return true;
}

bool PathChoice::hasWayOn(int block, End towards, const TrackState& state) const {
    for (const int id : graph_.connectionsFrom({block, towards})) {
        const trackgraph::Connection& connection = graph_.connection(id);
        if (!std::all_of(connection.turnouts.begin(), connection.turnouts.end(),
                         [](const trackgraph::TurnoutOnWay& turnout) { return turnout.article.has_value(); }))
            continue;
        // A train there facing the same way moves on; one facing this block would wait for this train.
        const std::optional<End> facing = state.trainFacing(connection.to.block);
        if (facing ? *facing != connection.to.end : state.blockFree(connection.to.block))
            return true;
    }
    return false;
}

bool PathChoice::isStation(int block, End towards) const {
    const trackgraph::Block& candidate = graph_.block(block);
    if (std::any_of(candidate.signalsAlong.begin(), candidate.signalsAlong.end(),
                    [&](const trackgraph::SignalOnTrack& signal) { return signal.towards == towards; }))
        return true;
    static const std::array<std::string, 6> words{"gleis", "bahnhof", "bf", "track", "platform", "station"};
    const std::string name = lowered(candidate.name);
    return std::any_of(words.begin(), words.end(),
                       [&](const std::string& word) { return name.find(word) != std::string::npos; });
}

} // namespace stellwerk::automation
