// Names in four-character segments (document 6.4.2, 6.7.4; notes B§3.7), against the trace's slave name
// "KS MS1" (#24-#26, #29) and locomotive name "003 131-0" (#77, #79, #81).

#include "mcan/NameSegments.h"

#include "mcan/Codec.h"

#include <gtest/gtest.h>
#include <string>

using namespace stellwerk;

namespace {

const mcan::Address SlaveOnSd{mcan::prio::Data, 0x0008, 43};
const mcan::Address MasterOnLoco{mcan::prio::Data, 0x0009, 42};

can::CanFrame frame(std::uint32_t id, std::initializer_list<std::uint8_t> data) {
    return can::CanFrame::extendedFrame(id, std::vector<std::uint8_t>(data));
}

TEST(NameSegments, KsMs1IsSentAsTheTraceSendsIt) {
    EXPECT_EQ(mcan::encode(mcan::nameSegment(SlaveOnSd, "KS MS1", 0)),
              frame(0x180020AB, {0x02, 0x00, 0x00, 0x00, 0x4B, 0x53, 0x20, 0x4D}));
    EXPECT_EQ(mcan::encode(mcan::nameSegment(SlaveOnSd, "KS MS1", 4)),
              frame(0x180020AB, {0x02, 0x00, 0x00, 0x04, 0x53, 0x31, 0x00}));
    EXPECT_EQ(mcan::encode(mcan::nameSegment(SlaveOnSd, "KS MS1", 8)),
              frame(0x180020AB, {0x02, 0x00, 0x00, 0x08, 0x00}));
    EXPECT_EQ(mcan::encode(mcan::nameSegment(SlaveOnSd, "KS MS1", 12)),
              frame(0x180020AB, {0x02, 0x00, 0x00, 0x0C, 0x00}));
}

TEST(NameSegments, SixteenCharactersFillFourSegmentsWithoutANul) {
    const std::string name = "MOBILE STATION 1";
    EXPECT_EQ(mcan::nameSegment(SlaveOnSd, name, 12).count, 4);
    EXPECT_EQ(mcan::encode(mcan::nameSegment(SlaveOnSd, name + "XYZ", 12)),
              mcan::encode(mcan::nameSegment(SlaveOnSd, name, 12)))
        << "cut to 16 characters";
}

TEST(NameSegments, TheTraceLocoNameIsJoinedUntilTheNul) {
    std::string name;
    bool ended = false;
    for (const can::CanFrame& f : {frame(0x180024AA, {0x02, 0x00, 0x00, 0x00, 0x30, 0x30, 0x33, 0x20}),
                                   frame(0x180024AA, {0x02, 0x00, 0x00, 0x04, 0x31, 0x33, 0x31, 0x2D}),
                                   frame(0x180024AA, {0x02, 0x00, 0x00, 0x08, 0x30, 0x00, 0x00, 0x00})}) {
        ASSERT_FALSE(ended);
        const auto segment = std::get<mcan::NameSegment>(mcan::decode(f, mcan::HandleRole::Loco));
        mcan::addSegment(name, segment);
        ended = mcan::endsName(segment);
    }
    EXPECT_TRUE(ended);
    EXPECT_EQ(name, "003 131-0");
}

TEST(NameSegments, AnOffsetZeroStartsANewNameAndAGapIsLeftOut) {
    std::string name = "OLD NAME";
    mcan::addSegment(name, mcan::nameSegment(MasterOnLoco, "NEW", 0));
    EXPECT_EQ(name, "NEW");
    mcan::addSegment(name, mcan::nameSegment(MasterOnLoco, "0123456789AB", 8));
    EXPECT_EQ(name, "NEW");
    EXPECT_TRUE(mcan::endsName(mcan::nameSegment(MasterOnLoco, "0123456789ABCDEF", 12)));
    EXPECT_FALSE(mcan::endsName(mcan::nameSegment(MasterOnLoco, "0123456789ABCDEF", 8)));
}

} // namespace
