#pragma once

#include "base/Expected.h"
#include "cs2/LocId.h"

#include <string>
#include <string_view>

namespace stellwerk::cs2 {

// A locomotive as a person writes it on a command line ("mfx:5", "dcc:3", "mm2:72", "sx1:4", "sx2:9", or a
// raw Loc-ID, "0x4005" or "16389"), and back; shared by stellwerk-cli and stellwerk-sim's --place. Errors
// are one sentence for the user.
Expected<LocId, std::string> parseLocomotive(std::string_view text);
// "mfx:5" for a loco in a known range, "0x1C05" otherwise.
std::string locomotiveText(LocId loco);

} // namespace stellwerk::cs2
