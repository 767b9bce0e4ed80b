#pragma once

#include "StationClient.h"

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::cli {

// The station commands that are one message and its acknowledgement: speed, direction, function,
// switch, stop, go, halt. Each prints one line: "ok: loco mfx:5 speed 500 (acknowledged)" on `out`, or
// "error: ..." with the reason on `err`. Returns nullopt when `command` is none of them.
std::optional<ParsedJob> parseDriveCommand(const std::string& command,
                                           const std::vector<std::string>& arguments, std::ostream& out,
                                           std::ostream& err);

} // namespace stellwerk::cli
