// Waits in the transports' messages read as a person says them: "trying again in 4 s", not "4000 ms".

#include "transport/DurationText.h"

#include <gtest/gtest.h>

using namespace std::chrono_literals;
using stellwerk::transport::durationText;

TEST(DurationText, WholeSecondsAreSaidInSeconds) {
    EXPECT_EQ(durationText(4000ms), QStringLiteral("4 s"));
    EXPECT_EQ(durationText(1000ms), QStringLiteral("1 s"));
    EXPECT_EQ(durationText(30000ms), QStringLiteral("30 s"));
}

TEST(DurationText, PartsOfASecondKeepTheirDecimals) {
    EXPECT_EQ(durationText(1500ms), QStringLiteral("1.5 s"));
    EXPECT_EQ(durationText(2250ms), QStringLiteral("2.25 s"));
}

TEST(DurationText, WaitsUnderASecondStayInMilliseconds) {
    EXPECT_EQ(durationText(250ms), QStringLiteral("250 ms"));
    EXPECT_EQ(durationText(0ms), QStringLiteral("0 ms"));
}
