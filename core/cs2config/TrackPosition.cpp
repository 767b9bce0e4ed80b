#include "cs2config/TrackPosition.h"

namespace stellwerk::cs2config {

std::optional<TrackPosition> TrackPosition::fromId(std::int64_t id) {
    if (id < 0 || id > std::int64_t{maxId})
        return std::nullopt;
    const auto bits = static_cast<std::uint32_t>(id);
    TrackPosition position;
    position.page = static_cast<std::uint8_t>(bits >> 16);
    position.row = static_cast<std::uint8_t>(bits >> 8);
    position.column = static_cast<std::uint8_t>(bits);
    return position;
}

} // namespace stellwerk::cs2config
