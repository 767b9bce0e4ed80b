#pragma once

#include "StationClient.h"

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace stellwerk::cli {

// The module refused the request (0xFE): it answered, but did not do it.
inline constexpr int RefusedByModule = 4;

// `ro --module req=ID,resp=ID[,std] [--json] [--timeout MS] read ADDRESS WIDTH | write ADDRESS WIDTH VALUE |
// switch RELAY on|off | watch [--seconds N]`: one RO relay/IO module on the station's bus, through
// Stellwerk's module session (relays and inputs where the simulator profile has them). Exit 0 when the module
// did it, 1 when it did not answer, 4 when it refused; nullopt for another command.
std::optional<ParsedJob> parseRoCommand(const std::string& command, const std::vector<std::string>& arguments,
                                        std::ostream& out, std::ostream& err);

} // namespace stellwerk::cli
