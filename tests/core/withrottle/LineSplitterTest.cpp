// "A newline can be a linefeed (0A hex), carriage return (0D hex), or a carriage return followed by a
// newline" (JMRI's protocol page, introduction); TCP cuts lines anywhere.
#include "withrottle/LineSplitter.h"

#include <gtest/gtest.h>

using stellwerk::withrottle::LineSplitter;
using Lines = std::vector<std::string>;

TEST(WiThrottleLines, EveryLineEnd) {
    LineSplitter splitter;
    EXPECT_EQ(splitter.feed("NPhone\nHUabc\r*+\r\nMTA*<;>V30\n"),
              (Lines{"NPhone", "HUabc", "*+", "MTA*<;>V30"}));
    EXPECT_EQ(splitter.bufferedBytes(), 0u);
}

TEST(WiThrottleLines, PartialLineWaitsForItsEnd) {
    LineSplitter splitter;
    EXPECT_TRUE(splitter.feed("MT+L3").empty());
    EXPECT_EQ(splitter.bufferedBytes(), 5u);
    EXPECT_EQ(splitter.feed("41<;>L341\r"), (Lines{"MT+L341<;>L341"}));
    // The \n of that \r\n arrives in the next segment: no empty line.
    EXPECT_EQ(splitter.feed("\n*\n"), (Lines{"*"}));
}

TEST(WiThrottleLines, OverlongLineIsDroppedWholeAndCounted) {
    LineSplitter splitter(8);
    EXPECT_EQ(splitter.feed("12345678\n"), (Lines{"12345678"}));
    EXPECT_TRUE(splitter.feed("123456789abc").empty());
    EXPECT_EQ(splitter.bufferedBytes(), 0u);
    EXPECT_TRUE(splitter.feed("def").empty());
    EXPECT_EQ(splitter.feed("ghi\nQ\n"), (Lines{"Q"}));
    EXPECT_EQ(splitter.overlongLines(), 1u);
}

TEST(WiThrottleLines, BufferNeverGrowsBeyondTheCap) {
    LineSplitter splitter(16);
    for (int i = 0; i < 1000; ++i)
        splitter.feed("xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx");
    EXPECT_LE(splitter.bufferedBytes(), 16u);
    EXPECT_EQ(splitter.overlongLines(), 1u);
}
