// RO frames as `stellwerk-cli decode` and the bus monitor show them.
#include "ro/FrameReport.h"

#include <gtest/gtest.h>

namespace stellwerk::ro {
namespace {

TEST(RoFrameReport, Section3_4_RelayWriteAsText) {
    const RoProfile profile = RoProfile::simulator(1);
    const FrameReport report(
        profile.requestFrame(Request{Request::Kind::Write, Width::Word, 0, 0x35, 0x2000}),
        Direction::Request);
    EXPECT_TRUE(report.decoded());
    EXPECT_EQ(
        report.text(),
        "01FE0001 8 13 00 00 35 00 20 00 00  ro.write-word  direction=request width=word address=0x0000 "
        "job=0x35 value=0x2000");
    EXPECT_EQ(report.json(),
              "{\"id\":\"01FE0001\",\"extended\":true,\"dlc\":8,\"data\":\"1300003500200000\","
              "\"name\":\"ro.write-word\",\"direction\":\"request\",\"fields\":{\"width\":\"word\","
              "\"address\":\"0x0000\",\"job\":\"0x35\",\"value\":\"0x2000\"}}");
    EXPECT_EQ(report.number("value"), 0x2000u);
}

TEST(RoFrameReport, DerivedAnswersAsText) {
    RoProfile profile = RoProfile::simulator(1);
    profile.ids = {0x100, 0x101, false};
    EXPECT_EQ(FrameReport(profile.answerFrame(OkAnswer{Width::Word, 0x36, 0x2000}), Direction::Answer).text(),
              "101 7 01 03 36 00 20 00 00  ro.ok  direction=answer width=word job=0x36 value=0x2000");
    EXPECT_EQ(FrameReport(profile.answerFrame(DuplicateJobAnswer{0x35}), Direction::Answer).text(),
              "101 2 FD 35  ro.duplicate-job  direction=answer job=0x35");
    EXPECT_EQ(FrameReport(profile.answerFrame(InvalidCommandAnswer{}), Direction::Answer).text(),
              "101 1 FE  ro.invalid-command  direction=answer");
}

TEST(RoFrameReport, AnUnknownPayloadSaysWhy) {
    const std::uint8_t bytes[] = {0x30, 0, 0, 0x36};
    const FrameReport report(can::CanFrame::extendedFrame(0x01FE0001, bytes), Direction::Request);
    EXPECT_FALSE(report.decoded());
    EXPECT_EQ(report.name(), "ro.unknown");
    EXPECT_EQ(report.detailText(), "direction=request error=\"COMMAND 0x30 is none of 0x11-0x14, 0x21-0x24 "
                                   "(004 §3.2.1, §3.2.2) (byte 1)\"");
    EXPECT_EQ(messageNames().size(), 12u);
}

} // namespace
} // namespace stellwerk::ro
