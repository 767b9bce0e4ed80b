#include "trackgraph/BlockNaming.h"

namespace stellwerk::trackgraph {

std::string BlockNaming::blockName(const Block& block) const {
    for (const ContactOnBlock& contact : block.contacts)
        if (!contact.label.empty())
            return contact.label;
    if (const std::optional<std::string> route = routeBeside(block))
        return *route;
    for (const SignalOnTrack& signal : block.signalsAlong)
        if (!signal.name.empty())
            return signal.name;
    return block.contacts.empty() ? "Block"
                                  : "Block " + std::to_string(block.contacts.front().contact.number);
}

// The first route button (in the order of the block's tiles from end a, then clockwise from north) on a
// place beside the block.
std::optional<std::string> BlockNaming::routeBeside(const Block& block) const {
    for (const TrackStep& step : block.path)
        for (int port = 0; port < GeometricPorts; ++port) {
            const std::optional<TileId> beside = tiles_.beside(step.tile, Port(port));
            if (!beside || tiles_.tile(*beside).type != "fahrstrasse")
                continue;
            const Tile& button = tiles_.tile(*beside);
            const std::string name = button.text.empty() ? routeName(button.article) : button.text;
            if (!name.empty())
                return name;
        }
    return std::nullopt;
}

std::string BlockNaming::signalName(const Tile& tile) const {
    if (!tile.text.empty() || !accessories_ || !tile.accessory)
        return tile.text;
    const bool secondOutput = tile.article % 2 == 1;
    for (const cs2config::Accessory& article : accessories_->accessories)
        if (article.id == *tile.accessory && article.secondOutput == secondOutput)
            return article.name;
    return {};
}

std::string BlockNaming::routeName(std::int64_t route) const {
    if (!routes_)
        return {};
    const cs2config::Route* found = routes_->find(route);
    return found ? found->name : std::string();
}

} // namespace stellwerk::trackgraph
