#pragma once

#include "base/Expected.h"
#include "trackgraph/TrackGraph.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace stellwerk::trackgraph {

// Where a locomotive is put on the track: in the block holding contact `contact` (the number as the S88
// tiles' `.artikel` write it, of any feedback device), its front towards the block end `towards` (a or b,
// as the track graph names them), running forward that way. One text for the simulator's and the
// automation's --place, so that both are told the same.
struct TrainPlacement {
    std::uint32_t locId = 0;
    std::int64_t contact = 0;
    End towards = End::B;

    friend bool operator==(const TrainPlacement&, const TrainPlacement&) = default;
};

// "LOC=CONTACT[:END]", LOC as the CLI writes it (mfx:5, dcc:3, mm2:72 or a Loc-ID), END a or b (b when left
// out). The error is one sentence about the text.
Expected<TrainPlacement, std::string> parsePlacement(std::string_view text);

} // namespace stellwerk::trackgraph
