#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace stellwerk::cs2config {

// A route step's `..sekunde` wait, written by the station in seconds with decimals ("2", "2.3", "3.2").
// Kept in milliseconds so that no float rounding changes a value on its way through the model.

// Milliseconds of "2.3" (2300); nullopt for text that is not a non-negative decimal with at most three
// decimals or is longer than 100 000 000 seconds.
std::optional<std::int64_t> parseRouteDelay(std::string_view text);
// "2.3" for 2300, "4" for 4000, "0.25" for 250; negative values are written as "0".
std::string formatRouteDelay(std::int64_t milliseconds);

} // namespace stellwerk::cs2config
