#pragma once

#include "trackgraph/TrainPlacement.h"

namespace stellwerk::automation {

// Where the user puts a train, as stellwerk-sim's --place reads it: the track graph's one text, so that the
// simulator and the automation are told the same.
using Placement = trackgraph::TrainPlacement;
using trackgraph::parsePlacement;

} // namespace stellwerk::automation
