// Standard (11-bit) frames in every notation: 3 hex digits, the candump convention.

#include "can/FrameText.h"

#include <gtest/gtest.h>

namespace stellwerk::can::test {
namespace {

const std::uint8_t TwoBytes[] = {0x01, 0x02};

TEST(FrameTextStandard, ThreeDigitIdsAreStandardInEveryNotation) {
    const CanFrame expected = CanFrame::standard(0x123, TwoBytes);
    for (const char* line : {"123#0102", "can0  123   [2]  01 02", "123 2 01 02", "0x123 2 01 02"}) {
        const auto parsed = parseFrame(line);
        ASSERT_TRUE(parsed) << line << ": " << parsed.error();
        EXPECT_EQ(parsed->frame, expected) << line;
    }
}

TEST(FrameTextStandard, EightDigitIdsStayExtendedEvenWhenSmall) {
    const auto parsed = parseFrame("00000123#0102");
    ASSERT_TRUE(parsed);
    EXPECT_TRUE(parsed->frame.extended);
    EXPECT_EQ(parsed->frame.id, 0x123u);
}

TEST(FrameTextStandard, StandardIdsAreWrittenWithThreeDigits) {
    const CanFrame frame = CanFrame::standard(0x7F, TwoBytes);
    EXPECT_EQ(formatCandump(frame), "07F#0102");
    EXPECT_EQ(formatDocument(frame), "07F 2 01 02");
    EXPECT_EQ(parseFrame(formatCandump(frame))->frame, frame) << "what is written reads back";
    EXPECT_EQ(formatCandump(CanFrame::extendedFrame(0x7F, TwoBytes)), "0000007F#0102");
}

TEST(FrameTextStandard, ThreeDigitsAboveSevenFfAreRefused) {
    const auto parsed = parseFrame("FFF#01");
    ASSERT_FALSE(parsed);
    EXPECT_NE(parsed.error().find("11 bits"), std::string::npos) << parsed.error();
}

} // namespace
} // namespace stellwerk::can::test
