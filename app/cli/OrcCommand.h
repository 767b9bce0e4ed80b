#pragma once

#include "StationClient.h"

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace stellwerk::cli {

// `orc [--json] [--seconds N] find | switch TARGET POS | watch`: Stellwerk as the OpenRailCAN central on the
// station's bus (orccentral::OrcSession). find lists the devices that answered within N s (default 1);
// switch sends `dekoder schalten` to a Ziel-Id and waits for the decoder's acknowledgement; watch prints
// devices, inputs and overloads as they come, for N s or until interrupted. Exit 0 when a device answered
// (switch: acknowledged), 1 when none did, 2 for a usage error; nullopt for another command.
std::optional<ParsedJob> parseOrcCommand(const std::string& command,
                                         const std::vector<std::string>& arguments, std::ostream& out,
                                         std::ostream& err);

} // namespace stellwerk::cli
