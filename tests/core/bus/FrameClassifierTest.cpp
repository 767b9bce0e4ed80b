// The classifier: which protocol a frame belongs to, given what a bus is expected to carry.

#include "bus/FrameClassifier.h"

#include <gtest/gtest.h>

namespace stellwerk::bus::test {
namespace {

using can::CanFrame;

const std::uint8_t Payload[] = {0x00, 0x00, 0x47, 0x11, 0x01};

TEST(FrameClassifier, ExtendedFramesBelongToTheCs2OnAStationBus) {
    // Document 1.2 example: the system command "go" from a Loc-ID 0x00004711.
    EXPECT_EQ(classify(CanFrame::extendedFrame(0x00004711, Payload), BusProfile::centralStation()),
              Protocol::Cs2);
}

TEST(FrameClassifier, StandardFramesAreForeignOnAStationBus) {
    EXPECT_EQ(classify(CanFrame::standard(0x123, Payload), BusProfile::centralStation()), Protocol::Foreign);
}

TEST(FrameClassifier, ABusThatExpectsNoCs2CallsEveryFrameForeign) {
    const BusProfile none{};
    EXPECT_EQ(classify(CanFrame::extendedFrame(0x00004711, Payload), none), Protocol::Foreign);
    EXPECT_FALSE(none.expects(Protocol::Cs2));
    EXPECT_TRUE(BusProfile::centralStation().expects(Protocol::Cs2));
}

TEST(FrameClassifier, ProtocolsHaveTheirJsonNames) {
    EXPECT_EQ(protocolName(Protocol::Cs2), "cs2");
    EXPECT_EQ(protocolName(Protocol::Foreign), "foreign");
}

} // namespace
} // namespace stellwerk::bus::test
