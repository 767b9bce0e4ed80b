#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace stellwerk::cli {

// `stellwerk-cli --station URL COMMAND ...`: talks to a command station over a transport (udp://,
// tcp://, can://; see stationUsage()). `arguments` start with the URL. Needs a QCoreApplication.
// Returns 0 when the station acknowledged, 1 when it did not (rejected, timed out, nothing answered),
// 2 on a usage error, 3 when the transport cannot be opened.
int runStation(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err);

// The usage lines of the station commands, for stellwerk-cli --help.
const char* stationUsage();

} // namespace stellwerk::cli
