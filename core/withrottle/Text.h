#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::withrottle {

// The WiThrottle protocol's delimiters (JMRI's protocol page, "String Parsing"): ]\[ between the entries
// of a list, }|{ between the parts of an entry, <;> between the parts of a throttle command.
inline constexpr std::string_view EntrySeparator = "]\\[";
inline constexpr std::string_view PartSeparator = "}|{";
inline constexpr std::string_view CommandSeparator = "<;>";

// A text as it can travel inside a line: control characters (a newline would end the line and start a
// command of its own) become spaces, and a delimiter inside the text is broken by a space in its middle.
std::string cleanText(std::string_view text);

std::vector<std::string_view> split(std::string_view text, std::string_view separator);

// A whole decimal number in [low, high]; nullopt for anything else (signs only where low < 0).
std::optional<int> parseNumber(std::string_view text, int low, int high);

} // namespace stellwerk::withrottle
