#pragma once

#include "StationClient.h"

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::cli {

// `resync [--stop]`: brings the layout back in step, the command line's answer to "I don't trust what I
// see". It reads the station's files and states, sends every locomotive the speed the station confirmed
// (with --stop: speed 0), reads every state again and prints one line per locomotive. Exit 0 when every
// command and question was answered, 1 otherwise. Returns nullopt when `command` is not resync.
std::optional<ParsedJob> parseResyncCommand(const std::string& command,
                                            const std::vector<std::string>& arguments, std::ostream& out,
                                            std::ostream& err);

} // namespace stellwerk::cli
