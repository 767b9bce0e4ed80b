#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace stellwerk::cli {

// `stellwerk-cli encode orc.<name> key=value ...`: an OpenRailCAN frame in the document's, candump's and
// the 13-byte network notation. 0 on success, 1 when the message is invalid, 2 on a usage error.
int runOrcEncode(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err);

// The ORC message names with their keys, for `encode --list`.
void printOrcNames(std::ostream& out);

} // namespace stellwerk::cli
