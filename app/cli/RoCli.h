#pragma once

#include "base/Expected.h"
#include "ro/RoProfile.h"

#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::cli {

// `stellwerk-cli encode ro.write|ro.read width=bit|byte|word|long address=N job=N [value=N]
// [size=4|8] [id=N [standard=true]]`: prints the payload of an RO request (004 §3.2), and with an id the
// frame in the document and candump notations. `arguments[0]` is "ro.write" or "ro.read".
int runRoEncode(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err);

// The ids of one RO module as `decode --ro-module` takes them: "req=ID,resp=ID[,std]" (hex with 0x, or
// decimal; "std" for 11-bit frames). The error says what is wrong.
Expected<ro::FrameIds, std::string> parseRoModule(std::string_view text);

} // namespace stellwerk::cli
