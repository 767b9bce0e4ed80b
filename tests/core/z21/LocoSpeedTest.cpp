// The speed tables of 4.2 (14, 28 and 128 steps) and the one conversion between Z21 steps and the
// station's speed 0..1000.
#include "z21/LocoSpeed.h"

#include <gtest/gtest.h>

using namespace stellwerk::z21;

TEST(Z21Speed, Section4_2_Table28StepsEveryStep) {
    // The table of 4.2, "R00V5 VVVV", forward: step n has the value n + 3 with its lowest bit in bit 4.
    const std::uint8_t table[29] = {0x00, 0x02, 0x12, 0x03, 0x13, 0x04, 0x14, 0x05, 0x15, 0x06,
                                    0x16, 0x07, 0x17, 0x08, 0x18, 0x09, 0x19, 0x0A, 0x1A, 0x0B,
                                    0x1B, 0x0C, 0x1C, 0x0D, 0x1D, 0x0E, 0x1E, 0x0F, 0x1F};
    for (std::uint8_t step = 0; step <= 28; ++step) {
        const LocoSpeed speed{SpeedStepMode::Steps28, true, step, false};
        EXPECT_EQ(speedByte(speed), 0x80 | table[step]) << "step " << int(step);
        EXPECT_EQ(speedFromByte(SpeedStepMode::Steps28, std::uint8_t(0x80 | table[step])), speed);
    }
}

TEST(Z21Speed, Section4_2_Table28StepsStopAndEmergencyStopBothForms) {
    EXPECT_EQ(speedFromByte(SpeedStepMode::Steps28, 0x10),
              (LocoSpeed{SpeedStepMode::Steps28, false, 0, false}));
    EXPECT_EQ(speedFromByte(SpeedStepMode::Steps28, 0x01),
              (LocoSpeed{SpeedStepMode::Steps28, false, 0, true}));
    EXPECT_EQ(speedFromByte(SpeedStepMode::Steps28, 0x11),
              (LocoSpeed{SpeedStepMode::Steps28, false, 0, true}));
    EXPECT_EQ(speedByte({SpeedStepMode::Steps28, false, 0, true}), 0x01);
}

TEST(Z21Speed, Section4_2_Tables14And128Steps) {
    EXPECT_EQ(speedByte({SpeedStepMode::Steps14, true, 14, false}), 0x8F);
    EXPECT_EQ(speedByte({SpeedStepMode::Steps14, false, 1, false}), 0x02);
    EXPECT_EQ(speedByte({SpeedStepMode::Steps14, true, 0, true}), 0x81);
    EXPECT_EQ(speedByte({SpeedStepMode::Steps128, true, 126, false}), 0xFF);
    EXPECT_EQ(speedByte({SpeedStepMode::Steps128, false, 3, false}), 0x04);
    EXPECT_EQ(speedFromByte(SpeedStepMode::Steps128, 0xFE),
              (LocoSpeed{SpeedStepMode::Steps128, true, 125, false}));
    EXPECT_EQ(speedFromByte(SpeedStepMode::Steps128, 0x01),
              (LocoSpeed{SpeedStepMode::Steps128, false, 0, true}));
    EXPECT_EQ(speedFromByte(SpeedStepMode::Steps14, 0x80),
              (LocoSpeed{SpeedStepMode::Steps14, true, 0, false}));
}

TEST(Z21Speed, StepAboveTheTopIsSentAsTheTop) {
    EXPECT_EQ(speedByte({SpeedStepMode::Steps14, true, 40, false}), 0x8F);
    EXPECT_EQ(speedByte({SpeedStepMode::Steps28, true, 40, false}), 0x9F);
    EXPECT_EQ(speedByte({SpeedStepMode::Steps128, true, 200, false}), 0xFF);
}

TEST(Z21Speed, EveryStepOfEveryModeRoundTrips) {
    for (const SpeedStepMode mode : {SpeedStepMode::Steps14, SpeedStepMode::Steps28, SpeedStepMode::Steps128})
        for (unsigned step = 0; step <= topStep(mode); ++step)
            for (const bool forward : {false, true}) {
                const LocoSpeed speed{mode, forward, std::uint8_t(step), false};
                EXPECT_EQ(speedFromByte(mode, speedByte(speed)), speed);
            }
}

TEST(Z21Speed, StationSpeedOfSteps) {
    EXPECT_EQ(systemSpeed({SpeedStepMode::Steps128, true, 0, false}), 0);
    EXPECT_EQ(systemSpeed({SpeedStepMode::Steps128, true, 1, false}), 1);
    EXPECT_EQ(systemSpeed({SpeedStepMode::Steps128, true, 126, false}), 1000);
    EXPECT_EQ(systemSpeed({SpeedStepMode::Steps28, true, 28, false}), 1000);
    EXPECT_EQ(systemSpeed({SpeedStepMode::Steps28, true, 14, false}), 482);
    EXPECT_EQ(systemSpeed({SpeedStepMode::Steps14, true, 14, false}), 1000);
    EXPECT_EQ(systemSpeed({SpeedStepMode::Steps14, true, 0, true}), 0);
}

TEST(Z21Speed, StepsOfStationSpeed) {
    EXPECT_EQ(stepForSystemSpeed(SpeedStepMode::Steps128, 0), 0);
    EXPECT_EQ(stepForSystemSpeed(SpeedStepMode::Steps128, 1), 1);
    EXPECT_EQ(stepForSystemSpeed(SpeedStepMode::Steps128, 500), 63);
    EXPECT_EQ(stepForSystemSpeed(SpeedStepMode::Steps128, 1000), 126);
    EXPECT_EQ(stepForSystemSpeed(SpeedStepMode::Steps28, 1023), 28);
    EXPECT_EQ(stepForSystemSpeed(SpeedStepMode::Steps14, 78), 2);
}

TEST(Z21Speed, StepToStationSpeedAndBackIsTheSameStep) {
    for (const SpeedStepMode mode : {SpeedStepMode::Steps14, SpeedStepMode::Steps28, SpeedStepMode::Steps128})
        for (unsigned step = 0; step <= topStep(mode); ++step)
            EXPECT_EQ(stepForSystemSpeed(mode, systemSpeed({mode, true, std::uint8_t(step), false})), step);
}

TEST(Z21Speed, ModeCodesOfDriveAndInfoDiffer) {
    EXPECT_EQ(driveCode(SpeedStepMode::Steps128), 3);
    EXPECT_EQ(infoCode(SpeedStepMode::Steps128), 4);
    EXPECT_EQ(modeFromDriveCode(2), SpeedStepMode::Steps28);
    EXPECT_EQ(modeFromInfoCode(2), SpeedStepMode::Steps28);
    EXPECT_FALSE(modeFromDriveCode(4));
    EXPECT_FALSE(modeFromInfoCode(3));
}
