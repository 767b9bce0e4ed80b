#include "mcan/NameSegments.h"

#include <algorithm>
#include <span>

namespace stellwerk::mcan {

namespace {

constexpr std::uint8_t LastOffset = 12;

} // namespace

NameSegment nameSegment(const Address& at, std::string_view name, std::uint8_t offset) {
    const std::string_view kept = name.substr(0, std::min(name.size(), MaximumNameLength));
    const std::string_view part = offset < kept.size() ? kept.substr(offset, 4) : std::string_view();
    NameSegment segment{at, offset, std::uint8_t(part.size()), {}, 0};
    std::copy(part.begin(), part.end(), segment.chars.begin());
    if (part.size() < 4) // the name ends here: a NUL says so
        segment.chars[segment.count++] = '\0';
    return segment;
}

bool endsName(const NameSegment& segment) {
    const auto chars = std::span(segment.chars).first(std::min<std::size_t>(segment.count, 4));
    return segment.offset >= LastOffset || std::ranges::find(chars, '\0') != chars.end();
}

void addSegment(std::string& name, const NameSegment& segment) {
    if (segment.offset == 0)
        name.clear();
    if (segment.offset > name.size() || segment.offset > LastOffset)
        return;
    name.resize(segment.offset);
    for (std::uint8_t i = 0; i < segment.count && i < 4 && segment.chars[i] != '\0'; ++i)
        name += segment.chars[i];
}

} // namespace stellwerk::mcan
