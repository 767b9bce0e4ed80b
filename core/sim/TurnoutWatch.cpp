#include "sim/TurnoutWatch.h"

#include "sim/AccessoryCommands.h"
#include "sim/SimulatedStation.h"

namespace stellwerk::sim {

namespace {

constexpr std::uint32_t MmAccessoryBase = 0x3000; // keyboard 1, when magnetartikel.cs2 names no protocol

} // namespace

TurnoutWatch::TurnoutWatch(const SimulatedStation& station, const trackgraph::TrackGraph& graph)
    : station_(station) {
    for (const trackgraph::Tile& tile : graph.tiles().tiles())
        if (tile.role() == trackgraph::TileRole::Turnout && tile.accessory && *tile.accessory >= 1)
            add(*tile.accessory);
}

void TurnoutWatch::add(std::int64_t article) {
    if (turnouts_.contains(article))
        return;
    Turnout turnout;
    turnout.locId = MmAccessoryBase + std::uint32_t(article) - 1;
    for (const cs2config::Accessory& accessory : station_.layout().accessories().accessories)
        if (accessory.id == article) {
            turnout.locId = AccessoryCommands::locIdOf(accessory);
            if (accessory.switchTimeMs && *accessory.switchTimeMs > 0)
                turnout.switchingTime = std::chrono::milliseconds(*accessory.switchTimeMs);
            break;
        }
    turnout.position = stationPosition(turnout);
    turnouts_.emplace(article, turnout);
}

int TurnoutWatch::stationPosition(const Turnout& turnout) const {
    const std::optional<std::uint8_t> position = station_.accessoryPosition(turnout.locId);
    return position ? int(*position) : UnknownPosition;
}

void TurnoutWatch::update(std::chrono::milliseconds elapsed) {
    for (auto& [article, turnout] : turnouts_) {
        turnout.stillMoving = std::max(turnout.stillMoving - elapsed, std::chrono::milliseconds(0));
        const int now = stationPosition(turnout);
        if (now != turnout.position) {
            turnout.position = now;
            turnout.stillMoving = turnout.switchingTime;
        }
    }
}

std::optional<int> TurnoutWatch::settled(std::int64_t article) const {
    const auto found = turnouts_.find(article);
    if (found == turnouts_.end())
        return UnknownPosition;
    if (found->second.stillMoving.count() > 0)
        return std::nullopt;
    return found->second.position;
}

bool TurnoutWatch::moving(std::int64_t article) const {
    const auto found = turnouts_.find(article);
    return found != turnouts_.end() && found->second.stillMoving.count() > 0;
}

trackgraph::PositionOf TurnoutWatch::positionOf() const {
    return [this](std::int64_t article) { return settled(article); };
}

} // namespace stellwerk::sim
