#pragma once

#include "StationClient.h"

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::cli {

// `ping`: lists every device that answers a ping (UID, software version, device type); status 1 when
// none answered. `status [UID]`: reads the status data of the device (of every device that answers a
// ping when no UID is given), polls each reading once (system 0x0B) and prints name, value and unit.
// Without a UID, a device that answers the ping but has no status data (a PC program) is named with its
// type and passed over: status 0 when every device with status data was read, 1 when a reading failed
// or no device had status data. With a UID, status 1 when anything of that device could not be read.
// Returns nullopt when `command` is neither.
std::optional<ParsedJob> parseDeviceCommand(const std::string& command,
                                            const std::vector<std::string>& arguments, std::ostream& out,
                                            std::ostream& err);

} // namespace stellwerk::cli
