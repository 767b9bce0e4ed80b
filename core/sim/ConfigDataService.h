#pragma once

#include "cs2config/ConfigStreamRequestCollector.h"
#include "sim/StationLayout.h"
#include "sim/StationState.h"

#include <optional>
#include <string>

namespace stellwerk::sim {

// Chapter 7: collects config-data requests (0x20, with their follow-up frames), acknowledges them
// and sends the file in the exact framing of a CS2 (ConfigStreamSender): the layout's files
// (loks, mags, fs, gbs, gbs-<n>), the MS2 streams built from them (lokinfo, loknamen, maginfo)
// and the status files built from the current state (lokstat/loksstat, magstat). A key the station
// has no file for is acknowledged without a stream, as can2lan (GBert/railroad) does.
class ConfigDataService {
public:
    ConfigDataService(const StationLayout& layout, const StationState& state)
        : layout_(layout), state_(state) {}

    bool handle(const cs2::Message& message, Outbox& out);

    // The contents the station sends for a complete request, or nullopt when it has none.
    std::optional<std::string> contentsFor(const cs2config::ConfigRequest& request) const;

private:
    std::optional<std::string> ms2Stream(const cs2config::ConfigRequest& request) const;
    std::optional<std::string> statusFile(std::string_view key) const;

    const StationLayout& layout_;
    const StationState& state_;
    cs2config::ConfigRequestCollector collector_;
};

} // namespace stellwerk::sim
