#pragma once

#include "StationClient.h"

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace stellwerk::cli {

// `download KEY [QUALIFIER] [-o FILE]`: fetches a configuration file (document chapter 7: loks, mags,
// fs, gbs, gbs-<n>, lokstat, ...; QUALIFIER is the follow-up text of loknamen/maginfo ("0 10") or the
// loco name of lokinfo), shows the progress on `err` and writes the file to FILE or `out`.
//
// `monitor [--json] [--count N]`: prints every frame received, one line each (text or JSON), until N
// frames arrived or Ctrl-C.
//
// Returns nullopt when `command` is neither.
std::optional<ParsedJob> parseTransferCommand(const std::string& command,
                                              const std::vector<std::string>& arguments, std::ostream& out,
                                              std::ostream& err);

} // namespace stellwerk::cli
