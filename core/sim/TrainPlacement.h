#pragma once

#include "base/Expected.h"
#include "cs2config/LocomotiveFile.h"
#include "trackgraph/TrackGraph.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::sim {

// Where a locomotive is put on the track: in the block holding contact `contact` (the number as the S88
// tiles' `.artikel` write it, of any feedback device), its front towards the block end `towards` (a or b,
// as the track graph names them), running forward that way. The train covers the contact, its front at the
// contact's far edge (further on when the train would not fit behind it).
struct TrainPlacement {
    std::uint32_t locId = 0;
    std::int64_t contact = 0;
    trackgraph::End towards = trackgraph::End::B;

    friend bool operator==(const TrainPlacement&, const TrainPlacement&) = default;
};

// stellwerk-sim's --place: "LOC=CONTACT[:END]", LOC as the CLI writes it (mfx:5, dcc:3, mm2:72 or a Loc-ID),
// END a or b (b when left out). The error is one sentence about the text.
Expected<TrainPlacement, std::string> parsePlacement(std::string_view text);

// The demo's trains as they stand when it starts: BR 218 Ost on Gleis 1, ICE 3 Velaro on Block 2, V 100 2023
// on Gleis 2 and Köf III on the Abstellgleis, each facing end b (the way round the loop, and the siding's
// buffer stops for the Köf).
std::vector<TrainPlacement> demoPlacements();

// Any other layout without --place: the first three locomotives of lokomotive.cs2 (fewer when it has fewer,
// or the plan fewer blocks), spread over the blocks in id order (train i of n in block 1 + i * blocks / n),
// each on its block's first contact facing end b.
std::vector<TrainPlacement> spreadPlacements(const cs2config::LocomotiveFile& locomotives,
                                             const trackgraph::TrackGraph& graph);

} // namespace stellwerk::sim
