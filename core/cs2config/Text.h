#pragma once

#include <string>
#include <string_view>

namespace stellwerk::cs2config {

// True when the bytes are well-formed UTF-8 (no overlong forms, no surrogates, at most U+10FFFF).
bool isValidUtf8(std::string_view bytes);
// Each byte read as a Latin-1 character, written as UTF-8 (the fallback for files that are not UTF-8).
std::string latin1ToUtf8(std::string_view bytes);
// The line shortened to at most `limit` characters with control bytes escaped, for messages.
std::string quoteForMessage(std::string_view line, std::size_t limit = 40);

} // namespace stellwerk::cs2config
