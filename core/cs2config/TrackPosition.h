#pragma once

#include <compare>
#include <cstdint>
#include <optional>

namespace stellwerk::cs2config {

// Where a tile sits on the CS2 track plan grid, and its packed form, the element's `.id`.
//
// The document (8.3.5) describes `.id` as "ssxxyy" (page, x, y). Real CS2 files and the renderers
// that read them pack it as page (bits 16-23), y/row (bits 8-15) and x/column (bits 0-7): drawn that
// way the corpus pages come out as the wide station layouts they are (karben.cs2: 14 x 4), drawn the
// document's way they come out tall and mirrored. We follow the field notes, not the document's text.
struct TrackPosition {
    static constexpr std::uint32_t maxId = 0xFFFFFF;

    std::uint8_t page = 0;
    std::uint8_t column = 0; // x
    std::uint8_t row = 0;    // y

    // The position packed in an `.id`; nullopt when the number has bits above the page byte or is negative.
    static std::optional<TrackPosition> fromId(std::int64_t id);
    std::uint32_t toId() const {
        return (std::uint32_t{page} << 16) | (std::uint32_t{row} << 8) | std::uint32_t{column};
    }

    friend auto operator<=>(const TrackPosition&, const TrackPosition&) = default;
};

} // namespace stellwerk::cs2config
