#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace stellwerk::cs2config {

// Numbers as .cs2 files write them: decimal ("-1", "200") or hexadecimal ("0x3e8"), with spaces
// around tolerated. nullopt when the text is not a number or does not fit.
std::optional<std::int64_t> parseInteger(std::string_view text);
// "0x3e8": lowercase without leading zeros, the way a CS2 writes uids and addresses.
std::string formatHex(std::uint64_t value);
std::string formatDecimal(std::int64_t value);
std::string_view trimmed(std::string_view text);

} // namespace stellwerk::cs2config
