#pragma once

#include "sim/StationLayout.h"
#include "sim/StationState.h"

namespace stellwerk::sim {

// Chapter 4: switches accessory decoders and remembers the position of each (the station's
// keyboard shows it; magstat serves it). The switch-off frame (current 0) is confirmed and keeps
// the position. Positions start from magnetartikel.cs2.
class AccessoryCommands {
public:
    AccessoryCommands(const StationLayout& layout, StationState& state);

    bool handle(const cs2::Message& message, Outbox& out);

    // The Loc-ID of a keyboard address (1-based) in the accessory's protocol ("mm2" or "dcc").
    static std::uint32_t locIdOf(const cs2config::Accessory& accessory);

private:
    StationState& state_;
};

} // namespace stellwerk::sim
