#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace stellwerk::cli {

// A whole decimal number, or hex with 0x, up to `max`; nullopt for anything else (signs, junk, overflow,
// too big). `wasHex` (optional) says which it was.
std::optional<std::uint32_t> parseNumber(std::string_view text,
                                         std::uint32_t max = std::numeric_limits<std::uint32_t>::max(),
                                         bool* wasHex = nullptr);

// "0x00FF" for (255, 4): ids, UIDs and values in the commands' output.
std::string hexNumber(std::uint32_t value, int digits);

} // namespace stellwerk::cli
