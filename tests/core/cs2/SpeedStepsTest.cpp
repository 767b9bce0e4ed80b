#include "cs2/SpeedSteps.h"

#include <gtest/gtest.h>

using stellwerk::cs2::effectiveSystemSpeed;
using stellwerk::cs2::SpeedSteps;

TEST(SpeedSteps, OnlyTheDocumentedStepCountsExist) {
    for (unsigned steps : {14u, 27u, 28u, 31u, 126u})
        EXPECT_TRUE(SpeedSteps::forStepCount(steps).has_value()) << steps;
    EXPECT_FALSE(SpeedSteps::forStepCount(15).has_value());
    EXPECT_FALSE(SpeedSteps::forStepCount(128).has_value());
}

TEST(SpeedSteps, TrackStepOneIsSystemSpeedOneAndZeroIsStandstill) {
    for (unsigned steps : {14u, 27u, 28u, 31u, 126u}) {
        const auto s = *SpeedSteps::forStepCount(steps);
        EXPECT_EQ(s.systemSpeed(1), 1);
        EXPECT_EQ(s.systemSpeed(0), 0);
        EXPECT_EQ(s.trackStep(0), 0u);
        EXPECT_EQ(s.trackStep(1), 1u);
    }
}

TEST(SpeedSteps, TopStepNeverExceedsSystemMaximum) {
    EXPECT_EQ(SpeedSteps::forStepCount(14)->systemSpeed(14), 1000);   // 1 + 13 * 77 = 1002, capped
    EXPECT_EQ(SpeedSteps::forStepCount(126)->systemSpeed(126), 1000); // 1 + 125 * 8 = 1001, capped
    EXPECT_EQ(SpeedSteps::forStepCount(28)->systemSpeed(28), 1000);
    EXPECT_EQ(SpeedSteps::forStepCount(27)->systemSpeed(27), 989);
}

TEST(SpeedSteps, SystemMaximumAndAboveSelectTheTopStep) {
    for (unsigned steps : {14u, 27u, 28u, 31u, 126u}) {
        const auto s = *SpeedSteps::forStepCount(steps);
        EXPECT_EQ(s.trackStep(1000), steps);
        EXPECT_EQ(s.trackStep(1023), steps) << "values up to 1023 mean maximum";
    }
}

TEST(SpeedSteps, EveryTrackStepSurvivesTheRoundTrip) {
    for (unsigned steps : {14u, 27u, 28u, 31u, 126u}) {
        const auto s = *SpeedSteps::forStepCount(steps);
        for (unsigned step = 0; step <= steps; ++step)
            EXPECT_EQ(s.trackStep(s.systemSpeed(step)), step) << steps << " steps, step " << step;
    }
}

TEST(SpeedSteps, TrackStepIsMonotonicInSystemSpeed) {
    const auto s = *SpeedSteps::forStepCount(28);
    unsigned last = 0;
    for (unsigned speed = 0; speed <= 1023; ++speed) {
        const unsigned step = s.trackStep(std::uint16_t(speed));
        EXPECT_GE(step, last);
        last = step;
    }
}

TEST(SpeedSteps, WireValuesAboveOneThousandCountAsMaximum) {
    EXPECT_EQ(effectiveSystemSpeed(500), 500);
    EXPECT_EQ(effectiveSystemSpeed(1000), 1000);
    EXPECT_EQ(effectiveSystemSpeed(1023), 1000);
}
