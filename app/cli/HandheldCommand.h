#pragma once

#include "StationClient.h"

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace stellwerk::cli {

// `handhelds [--json] [--master | --watch] [--seconds N]`: Stellwerk as the M-CAN master of the MS1
// handhelds on the station's bus (or, with --watch or beside a Central Station, their watcher), one line per
// event until Ctrl+C (or N seconds); nullopt for another command.
std::optional<ParsedJob> parseHandheldCommand(const std::string& command,
                                              const std::vector<std::string>& arguments, std::ostream& out,
                                              std::ostream& err);

} // namespace stellwerk::cli
