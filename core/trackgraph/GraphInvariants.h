#pragma once

#include "trackgraph/TrackGraph.h"

#include <string>
#include <vector>

namespace stellwerk::trackgraph {

// What must hold for any derived graph, whatever the pages were (the tests and the `track_graph` fuzz
// target check it): every contact in at most one block; ids count from 1 in order; every connection joins
// two existing block ends, needs positions that set the legs it passes and conflicts both ways; every
// block's path runs from its end a to its end b over joined track, and its tiles know it; every problem is
// on a tile. Returns one sentence per broken rule (empty when all hold).
std::vector<std::string> brokenInvariants(const TrackGraph& graph);

} // namespace stellwerk::trackgraph
