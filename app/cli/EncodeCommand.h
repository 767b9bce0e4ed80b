#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace stellwerk::cli {

// `stellwerk-cli encode <name> key=value ...`: builds the frame and prints it in the document's,
// candump's and the 13-byte network notation. Returns 0 on success, 1 when the message is invalid,
// 2 on a usage error.
int runEncode(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err);

} // namespace stellwerk::cli
