#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace stellwerk::cli {

// `stellwerk-cli decode [--json] [FRAME ...]`: one line of output per frame, from arguments or,
// when none are given, from standard input (blank lines and lines starting with '#' are skipped).
// Returns 0 when every frame decoded, 1 when any did not, 2 on a usage error.
int runDecode(const std::vector<std::string>& arguments, std::istream& in, std::ostream& out,
              std::ostream& err);

} // namespace stellwerk::cli
