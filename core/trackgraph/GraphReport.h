#pragma once

#include "cs2config/JsonWriter.h"
#include "trackgraph/TrackGraph.h"

#include <string>

namespace stellwerk::trackgraph {

// `stellwerk-cli layout graph DIR`: the blocks, connections and problems as lines a person reads.
std::string describeGraph(const TrackGraph& graph);

// `stellwerk-cli layout graph DIR --json`: one JSON document with "pages", "blocks", "connections" and
// "problems" (docs/guide/track-graph.md describes every field).
std::string toJson(const TrackGraph& graph);
void writeJson(cs2config::JsonWriter& json, const TrackGraph& graph);

} // namespace stellwerk::trackgraph
