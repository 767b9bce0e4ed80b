#pragma once

#include "sim/StationLayout.h"
#include "sim/StationState.h"

#include <string>

namespace stellwerk::sim {

// lokomotive.sr2 (keys lokstat/loksstat) from the station's state: speed, direction and functions
// of every locomotive of the layout, in the mrsystem format that cs2config reads.
std::string locomotiveStatusFile(const StationLayout& layout, const StationState& state);
// magnetartikel.sr2 (key magstat): the position of every accessory of the layout.
std::string accessoryStatusFile(const StationLayout& layout, const StationState& state);

} // namespace stellwerk::sim
