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

bool PathChoice::usable(const trackgraph::Connection& connection, const TrackState& state) const {
    return state.connectionFree(connection.id) &&
           std::all_of(connection.turnouts.begin(), connection.turnouts.end(),
                       [](const trackgraph::TurnoutOnWay& turnout) { return turnout.article.has_value(); });
}

bool PathChoice::canStop(int block, End towards, int trainLengthMm, const TrackState& state) const {
    return graph_.block(block).lengthMm >= trainLengthMm && hasWayOn(block, towards, state);
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
