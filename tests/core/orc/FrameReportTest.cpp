// The ORC frame report: one text line and one JSON object per frame, in the shape of the M-CAN report.

#include "orc/FrameReport.h"

#include "can/FrameText.h"

#include <gtest/gtest.h>

using namespace stellwerk;
using namespace stellwerk::orc;

namespace {
can::CanFrame reportedFrame(std::string_view text) {
    return can::parseFrame(text)->frame;
}
} // namespace

// Notes A4.2 V5 (Derived): the MM2 turnout 5 with its legacy range named.
TEST(FrameReport, DecoderSwitchNamesTheLegacyTarget) {
    const FrameReport report(reportedFrame("11100000 4 03 30 05 01"));
    EXPECT_EQ(report.text(), "11100000 4 03 30 05 01  orc.decoder.switch  prio=2 type=system sender=0x0000 "
                             "direction=command target=0x3005 legacy=mm2-decoder number=5 position=1");
    EXPECT_TRUE(report.decoded());
}

// Notes A4.2 V8 (Derived) as JSON.
TEST(FrameReport, EncoderEventAsJson) {
    const FrameReport report(reportedFrame("17122E01 4 10 2E 01 05"));
    EXPECT_EQ(
        report.json(),
        "{\"id\":\"17122E01\",\"dlc\":4,\"data\":\"102E0105\",\"name\":\"orc.encoder.status\",\"fields\":{"
        "\"prio\":2,\"type\":\"can-encoder\",\"sender\":\"0x2E01\",\"direction\":\"command\","
        "\"encoder\":\"0x2E01\",\"inputCount\":8,\"inputs\":\"0x05\",\"event\":\"event\"}}");
    EXPECT_EQ(report.number("inputs"), std::optional<std::uint64_t>(5));
}

TEST(FrameReport, ExtensionSaysSo) {
    const FrameReport report(reportedFrame("1D212E03 7 02 3A 2E 2E 01 2E 03"));
    EXPECT_EQ(report.name(), "orc.mgmt.assign");
    EXPECT_NE(report.detailText().find("extension=true"), std::string::npos) << report.detailText();
}

TEST(FrameReport, UnknownFrameGivesItsReason) {
    const FrameReport report(reportedFrame("11100000 3 03 30 05"));
    EXPECT_FALSE(report.decoded());
    EXPECT_NE(report.text().find("why=\"dekoder schalten takes DLC 4 (Ziel-Id, Pos)\""), std::string::npos)
        << report.text();
}
