#pragma once

#include "cs2config/JsonWriter.h"
#include "cs2config/Locomotive.h"

#include <string_view>

namespace stellwerk::cs2config {

// One locomotive as a JSON object (uids in hex as the files write them), shared by the JSON of
// lokomotive.cs2 and of the MS2 lokinfo stream.
void writeLocomotiveJson(JsonWriter& json, std::string_view key, const Locomotive& locomotive);

std::string_view directionName(TravelDirection direction); // "forward", "backward", "unknown"
std::string_view triggerName(FunctionTrigger trigger);     // "latching", "momentary", "timed", "unknown"

} // namespace stellwerk::cs2config
