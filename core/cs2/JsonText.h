#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace stellwerk::cs2 {

// Length of the well-formed UTF-8 sequence at bytes[i] (1 for ASCII), or 0 when the byte there does not
// start one (no overlong forms, no surrogates, at most U+10FFFF).
std::size_t utf8SequenceLength(std::string_view bytes, std::size_t i);

// `text` as a quoted JSON string that every JSON reader accepts, whatever its bytes: well-formed UTF-8
// is kept as it is, every other byte is read as Latin-1 (0xE4 -> "\u00e4"), control characters and DEL
// are escaped. The one escaping rule of all of Stellwerk's JSON output.
std::string jsonQuoted(std::string_view text);

} // namespace stellwerk::cs2
