#pragma once

#include "base/Expected.h"
#include "trackgraph/TrackGraph.h"

#include <filesystem>
#include <string>

namespace stellwerk::station {
struct StartupResult;
}

namespace stellwerk::automation {

// The track graph the automation runs on, from the layout in use: the station's download (the start-up's
// pages, accessories and routes) or a layout folder. The one seam to switch to model::LayoutInUse.
trackgraph::TrackGraph graphOf(const station::StartupResult& startup);
// The folder holding config/, or config/ itself; the error says why it has no usable plan.
Expected<trackgraph::TrackGraph, std::string> graphOfFolder(const std::filesystem::path& folder);

} // namespace stellwerk::automation
