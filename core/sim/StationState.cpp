#include "sim/StationState.h"

namespace stellwerk::sim {

SimulatedLoco& StationState::loco(std::uint32_t locId) {
    auto [it, added] = locos.try_emplace(locId);
    if (added)
        it->second.locId = locId;
    return it->second;
}

const SimulatedLoco* StationState::findLoco(std::uint32_t locId) const {
    const auto it = locos.find(locId);
    return it == locos.end() ? nullptr : &it->second;
}

} // namespace stellwerk::sim
