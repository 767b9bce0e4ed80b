#pragma once

#include "mcan/Messages.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace stellwerk::mcan {

// A name (the slave's, a locomotive's) travels in segments of four characters at offsets 0, 4, 8 and 12
// (document 6.4.2, 6.7.4, 7.5): at most 16 characters, ended by a NUL in the segment where it ends, which is
// then shorter (notes B§3.7; trace #24-#29: "KS M", "S1" NUL, NUL, NUL).
inline constexpr std::size_t MaximumNameLength = 16;

// The segment at `offset` of `name` (cut to 16 characters), sent from `at`.
NameSegment nameSegment(const Address& at, std::string_view name, std::uint8_t offset);

// Whether the segment is the last of its name: it holds a NUL, or it is the one at offset 12.
bool endsName(const NameSegment& segment);

// Puts the segment's characters into `name` at its offset (offset 0 starts a new name); a segment whose
// offset is beyond what `name` holds so far is left out, so that `name` never has a gap.
void addSegment(std::string& name, const NameSegment& segment);

} // namespace stellwerk::mcan
