#pragma once

#include "StationClient.h"

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::cli {

// `serve [--z21 [HOST:]PORT] [--withrottle [HOST:]PORT] [--seconds N] [--json]`: reads the station and puts
// the phone servers in front of its railway (the Z21 LAN server, default port 21105, and the WiThrottle
// server, default port 12090; with neither option the Z21 server alone on all interfaces), printing one line
// per client event until N seconds pass or Ctrl-C; then every locomotive its clients drove is stopped.
// Exit 0, or 3 when a server cannot listen. Nullopt when `command` is not serve.
std::optional<ParsedJob> parseServeCommand(const std::string& command,
                                           const std::vector<std::string>& arguments, std::ostream& out,
                                           std::ostream& err);

} // namespace stellwerk::cli
