#pragma once

#include "cs2config/LocomotiveFile.h"
#include "trackgraph/TrackGraph.h"
#include "trackgraph/TrainPlacement.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::sim {

// Where a locomotive is put on the track, and stellwerk-sim's --place text: the track graph's. The simulator
// puts the train over the contact, its front at the contact's far edge (further on when the train would not
// fit behind it).
using trackgraph::parsePlacement;
using trackgraph::TrainPlacement;

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
