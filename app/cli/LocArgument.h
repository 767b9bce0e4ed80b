#pragma once

#include "base/Expected.h"
#include "cs2/LocId.h"
#include "cs2/Messages.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace stellwerk::cli {

// The words a person types for locomotives, accessories and their settings on the command line, turned
// into wire values, and wire values written back the same way. Errors are one sentence for the user.

// A locomotive: "mfx:5", "dcc:3", "mm2:72", "sx1:4", "sx2:9", or a raw Loc-ID ("0x4005", "16389").
Expected<cs2::LocId, std::string> parseLocomotive(std::string_view text);
// An accessory by its 1-based keyboard number: "5" or "mm2:5" (MM accessory 5 = 0x3004), "dcc:5"
// (0x3804), "sx1:5", or a raw Loc-ID written in hex ("0x3004").
Expected<cs2::LocId, std::string> parseAccessory(std::string_view text);
// "mfx:5" for a loco in a known range, "0x1C05" otherwise.
std::string locomotiveText(cs2::LocId loco);
// "mm2:5", "dcc:12", "sx1:3" (1-based keyboard numbers), "0x2C00" otherwise.
std::string accessoryText(cs2::LocId article);

// forward, backward or toggle (also 1, 2, 3).
Expected<cs2::Direction, std::string> parseDirection(std::string_view text);
std::string_view directionText(std::uint8_t direction);
// A system speed 0..1000.
Expected<std::uint16_t, std::string> parseSpeed(std::string_view text);
// A function number 0..31.
Expected<std::uint8_t, std::string> parseFunctionNumber(std::string_view text);
// on or off (also 1, 0).
Expected<bool, std::string> parseOnOff(std::string_view text);
// An accessory position 0..255 or its name in document 4.1: red/round/right/off/hp0 = 0,
// green/straight/on/hp1 = 1, yellow/left/hp2 = 2, white/sh0 = 3.
Expected<std::uint8_t, std::string> parsePosition(std::string_view text);
// A device UID, decimal or hex ("0x43533201").
Expected<std::uint32_t, std::string> parseUid(std::string_view text);

} // namespace stellwerk::cli
