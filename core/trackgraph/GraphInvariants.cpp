#include "trackgraph/GraphInvariants.h"

#include <algorithm>
#include <map>

namespace stellwerk::trackgraph {

namespace {

std::string blockText(const Block& block) {
    return "block " + std::to_string(block.id) + " '" + block.name + "'";
}

void checkContacts(const TrackGraph& graph, std::vector<std::string>& broken) {
    std::map<ContactKey, int> owner;
    for (const Block& block : graph.blocks())
        for (const ContactOnBlock& contact : block.contacts) {
            const auto [found, fresh] = owner.emplace(contact.contact, block.id);
            if (!fresh)
                broken.push_back("contact " + std::to_string(contact.contact.number) + " is in block " +
                                 std::to_string(found->second) + " and in " + blockText(block));
        }
}

bool pathJoins(const TrackGraph& graph, const std::vector<TrackStep>& path) {
    for (std::size_t i = 1; i < path.size(); ++i) {
        const Tile& before = graph.tile(path[i - 1].tile);
        const Tile& after = graph.tile(path[i].tile);
        const bool sameDrawing = before.page == after.page;
        if (sameDrawing && path[i].entry != facing(path[i - 1].exit))
            return false;
        if (!sameDrawing && (path[i].entry != Port::Link || path[i - 1].exit != Port::Link))
            return false;
    }
    return true;
}

void checkBlocks(const TrackGraph& graph, std::vector<std::string>& broken) {
    for (std::size_t i = 0; i < graph.blocks().size(); ++i) {
        const Block& block = graph.blocks()[i];
        if (block.id != int(i + 1))
            broken.push_back(blockText(block) + " is number " + std::to_string(i + 1) + " in the list");
        if (block.path.empty() || block.contacts.empty()) {
            broken.push_back(blockText(block) + " has no track or no contact");
            continue;
        }
        if (block.path.front().tile != block.end(End::A).tile ||
            block.path.front().entry != block.end(End::A).port ||
            block.path.back().tile != block.end(End::B).tile ||
            block.path.back().exit != block.end(End::B).port)
            broken.push_back(blockText(block) + "'s path does not run from its end a to its end b");
        if (!pathJoins(graph, block.path))
            broken.push_back(blockText(block) + "'s path is not joined track");
        for (const TileId tile : block.tiles) {
            const std::vector<int> at = graph.blocksAt(tile);
            if (std::find(at.begin(), at.end(), block.id) == at.end())
                broken.push_back(blockText(block) + "'s tile " + std::to_string(tile) + " does not know it");
        }
    }
}

bool existing(const TrackGraph& graph, const BlockEnd& end) {
    return end.block >= 1 && end.block <= int(graph.blocks().size());
}

void checkConnection(const TrackGraph& graph, const Connection& connection,
                     std::vector<std::string>& broken) {
    const std::string name = "connection " + std::to_string(connection.id);
    if (!existing(graph, connection.from) || !existing(graph, connection.to)) {
        broken.push_back(name + " joins a block end that does not exist");
        return;
    }
    for (const TurnoutOnWay& turnout : connection.turnouts)
        if (turnout.position < 0 || turnout.position > 7 || !((turnout.legMask >> turnout.position) & 1U))
            broken.push_back(name + " needs a position that does not set the leg it passes");
    if (!pathJoins(graph, connection.path))
        broken.push_back(name + "'s path is not joined track");
    for (const int other : connection.conflicts) {
        if (other < 1 || other > int(graph.connections().size()) || other == connection.id) {
            broken.push_back(name + " conflicts with a connection that does not exist");
            continue;
        }
        const std::vector<int>& back = graph.connection(other).conflicts;
        if (!std::binary_search(back.begin(), back.end(), connection.id))
            broken.push_back(name + " conflicts with " + std::to_string(other) + ", but not the other way");
    }
}

} // namespace

std::vector<std::string> brokenInvariants(const TrackGraph& graph) {
    std::vector<std::string> broken;
    checkContacts(graph, broken);
    checkBlocks(graph, broken);
    for (std::size_t i = 0; i < graph.connections().size(); ++i) {
        if (graph.connections()[i].id != int(i + 1))
            broken.push_back("connection " + std::to_string(graph.connections()[i].id) + " is number " +
                             std::to_string(i + 1) + " in the list");
        checkConnection(graph, graph.connections()[i], broken);
    }
    for (const Problem& problem : graph.problems())
        if (problem.tile >= graph.tiles().size())
            broken.push_back("a problem is on a tile that does not exist: " + problem.text);
    return broken;
}

} // namespace stellwerk::trackgraph
