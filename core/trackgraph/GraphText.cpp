// The text of `stellwerk-cli layout graph`: one paragraph per block, a line per connection and problem.
#include "trackgraph/GraphReport.h"

#include <sstream>

namespace stellwerk::trackgraph {

namespace {

std::string counted(std::size_t n, const std::string& what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

std::string place(const TrackGraph& graph, TileId tile) {
    const Tile& t = graph.tile(tile);
    return "page " + describePage(graph.pages()[t.page]) + " column " + std::to_string(t.place.column) +
           " row " + std::to_string(t.place.row);
}

std::string blockLabel(const TrackGraph& graph, const BlockEnd& end) {
    const Block& block = graph.block(end.block);
    return "block " + std::to_string(block.id) + " '" + block.name + "' " + std::string(endName(end.end));
}

template <typename List, typename Format>
std::string listed(const List& items, Format format) {
    std::string text;
    for (const auto& item : items)
        text += (text.empty() ? "" : ", ") + format(item);
    return text;
}

void describeBlock(std::ostream& out, const TrackGraph& graph, const Block& block) {
    out << "  " << block.id << " '" << block.name << "': contacts "
        << listed(block.contacts, [](const ContactOnBlock& c) { return std::to_string(c.contact.number); })
        << "; " << counted(std::size_t(block.lengthTiles()), "tile") << ", " << block.lengthMm << " mm\n";
    for (const End end : {End::A, End::B}) {
        const BlockEndInfo& info = block.end(end);
        out << "      " << endName(end) << ": " << place(graph, info.tile) << " (" << portName(info.port)
            << "), then " << endKindName(info.beyond) << "\n";
    }
    for (const SignalOnTrack& signal : block.signalsAlong)
        out << "      signal " << (signal.name.empty() ? "(no name)" : "'" + signal.name + "'") << " at "
            << signal.atMm << " mm, for trains towards " << endName(signal.towards) << "\n";
}

std::string turnoutText(const TurnoutOnWay& turnout) {
    return "turnout " + (turnout.article ? std::to_string(*turnout.article) : std::string("(no article)")) +
           " " + std::string(positionName(turnout.kind, turnout.position));
}

void describeConnection(std::ostream& out, const TrackGraph& graph, const Connection& connection) {
    out << "  " << connection.id << " " << blockLabel(graph, connection.from) << " -> "
        << blockLabel(graph, connection.to) << ": ";
    out << (connection.turnouts.empty() ? "no turnout" : listed(connection.turnouts, turnoutText));
    out << "; " << counted(connection.path.size(), "tile") << ", " << connection.lengthMm << " mm";
    if (!connection.crossings.empty())
        out << "; over the crossing at "
            << listed(connection.crossings, [&](TileId t) { return place(graph, t); });
    if (!connection.routes.empty())
        out << "; routes " << listed(connection.routes, [](std::int64_t r) { return std::to_string(r); });
    if (!connection.conflicts.empty())
        out << "; conflicts with " << listed(connection.conflicts, [](int c) { return std::to_string(c); });
    out << "\n";
}

} // namespace

std::string describeGraph(const TrackGraph& graph) {
    std::ostringstream out;
    out << counted(graph.blocks().size(), "block") << ", "
        << counted(graph.connections().size(), "connection") << ", "
        << counted(graph.problems().size(), "problem") << " on " << counted(graph.pages().size(), "page")
        << "\n";
    out << "\nBlocks:\n";
    for (const Block& block : graph.blocks())
        describeBlock(out, graph, block);
    out << "\nConnections:\n";
    for (const Connection& connection : graph.connections())
        describeConnection(out, graph, connection);
    out << "\nProblems:\n";
    for (const Problem& problem : graph.problems())
        out << "  " << describePlace(graph.tiles(), problem.tile) << ": " << problem.text << "\n";
    return out.str();
}

} // namespace stellwerk::trackgraph
