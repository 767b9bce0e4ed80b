#pragma once

#include "StationClient.h"

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::cli {

// `ping`: lists every device that answers a ping (UID, software version, device type); status 1 when
// none answered. `status [UID]`: reads the status data of the device (of every device that answers a
// ping when no UID is given), polls each reading once (system 0x0B) and prints name, value and unit;
// status 1 when something could not be read. Returns nullopt when `command` is neither.
std::optional<ParsedJob> parseDeviceCommand(const std::string& command,
                                            const std::vector<std::string>& arguments, std::ostream& out,
                                            std::ostream& err);

} // namespace stellwerk::cli
