#include "cs2config/TrackPosition.h"

#include <gtest/gtest.h>

using namespace stellwerk::cs2config;

namespace {

TrackPosition at(int page, int column, int row) {
    return {static_cast<std::uint8_t>(page), static_cast<std::uint8_t>(column),
            static_cast<std::uint8_t>(row)};
}

} // namespace

// Document 8.3.5: ".id=0x010301 ... (also Seite=1, x=3, y=1)". Real files and their renderers read the
// middle byte as the row and the low byte as the column (field notes, "Files"), so this tile is on page 1,
// column 1, row 3.
TEST(TrackPosition, DocumentIdReadTheWayRealFilesAre) {
    EXPECT_EQ(TrackPosition::fromId(0x010301), at(1, 1, 3));
}

// The element of the document's gleisbild.cs2 example (8.3): ".id=0x301".
TEST(TrackPosition, DocumentExampleElement) {
    EXPECT_EQ(TrackPosition::fromId(0x301), at(0, 1, 3));
}

TEST(TrackPosition, KarbenTilesAreAWideLayout) {
    // 0x10c is the right end of karben.cs2's first row, 0x301 the left end of its last.
    EXPECT_EQ(TrackPosition::fromId(0x10c), at(0, 12, 1));
    EXPECT_EQ(TrackPosition::fromId(0x301), at(0, 1, 3));
}

TEST(TrackPosition, ConvertsBothWays) {
    for (const std::uint32_t id : {0x0u, 0x1u, 0x100u, 0x10au, 0xd14u, 0x1e10u, 0xff00ffu, 0xffffffu})
        EXPECT_EQ(TrackPosition::fromId(id)->toId(), id) << std::hex << id;
    EXPECT_EQ(at(2, 0x1e, 0x10).toId(), 0x02101eu);
}

TEST(TrackPosition, RejectsIdsThatAreNoPosition) {
    EXPECT_FALSE(TrackPosition::fromId(-1));
    EXPECT_FALSE(TrackPosition::fromId(0x1000000));
    EXPECT_FALSE(TrackPosition::fromId(INT64_MAX));
}

TEST(TrackPosition, MissingIdMeansTheOrigin) {
    EXPECT_EQ(TrackPosition{}, at(0, 0, 0));
    EXPECT_EQ(TrackPosition{}.toId(), 0u);
}
