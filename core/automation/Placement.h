#pragma once

#include "base/Expected.h"
#include "trackgraph/TrackGraph.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace stellwerk::automation {

// Where the user puts a train: the block holding the contact, facing the end `towards`.
struct Placement {
    std::uint32_t locId = 0;
    std::int64_t contact = 0;
    trackgraph::End towards = trackgraph::End::B;
};

// "LOC=CONTACT[:END]" as stellwerk-sim's --place reads it (LOC: mfx:5, dcc:3, mm2:72 or a Loc-ID; END a or b,
// b when left out), so that the simulator and the automation are told the same text.
Expected<Placement, std::string> parsePlacement(std::string_view text);

} // namespace stellwerk::automation
