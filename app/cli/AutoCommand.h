#pragma once

#include "StationClient.h"

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::cli {

// `auto run [--layout DIR] --place LOC=CONTACT[:END]... [--seconds N] [--json]`: reads the station, switches
// the track power on, places the trains on the track graph of the station's plan (or of DIR's), runs them
// automatically (automation::Automation) and prints one line per event; at the end (N seconds, default 60,
// or Ctrl-C) stops every train it drove, waits until the station confirmed it, gives back every reservation
// and prints a summary line. Exit 0 when no fault occurred, 1 otherwise. Nullopt when `command` is not auto.
std::optional<ParsedJob> parseAutoCommand(const std::string& command,
                                          const std::vector<std::string>& arguments, std::ostream& out,
                                          std::ostream& err);

} // namespace stellwerk::cli
