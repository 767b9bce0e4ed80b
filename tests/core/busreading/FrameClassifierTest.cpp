// The classifier: which protocol a frame belongs to, given what a bus is expected to carry.

#include "busreading/FrameClassifier.h"

#include <gtest/gtest.h>

namespace stellwerk::busreading::test {
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
    EXPECT_EQ(protocolName(Protocol::Mcan), "mcan");
    EXPECT_EQ(protocolName(Protocol::Foreign), "foreign");
}

// M-CAN notes B§6.2 and B§6.3: MS1 handhelds share the CS2's bus, and a station's bus expects both.
TEST(FrameClassifier, McanFramesBelongToMcanOnAStationBus) {
    const BusProfile station = BusProfile::centralStation();
    EXPECT_TRUE(station.expects(Protocol::Mcan));
    const std::uint8_t poll[] = {0x00, 0x00, 0x00, 0x2A};
    EXPECT_EQ(classify(CanFrame::extendedFrame(0x0C0007AB, poll), station), Protocol::Mcan); // trace #82
    EXPECT_EQ(classify(CanFrame::extendedFrame(0x1C00007E, {}), station), Protocol::Mcan);   // login stage 0
    EXPECT_EQ(classify(CanFrame::extendedFrame(0x1C0800FF, Payload), station), Protocol::Mcan); // flash
    const std::uint8_t zeros[8] = {};
    EXPECT_EQ(classify(CanFrame::extendedFrame(0x380, zeros), station), Protocol::Mcan); // "CAN-Bus belegt"
}

// The CS2 marks its hashes with 110 in bits 9..7 (CS2 document 1.2.4), which M-CAN never uses: the marker
// wins even with priority bits set.
TEST(FrameClassifier, TheCs2HashMarkerWinsOverThePriorityBits) {
    const BusProfile station = BusProfile::centralStation();
    EXPECT_EQ(classify(CanFrame::extendedFrame(0x0C084B11, Payload), station), Protocol::Cs2);
    EXPECT_EQ(classify(CanFrame::extendedFrame(0x1C00037E, {}), station), Protocol::Cs2);
}

// An MS2's plain hash or a Gleisbox's swapped one has no marker; with priority 0 it stays the CS2's, and so
// do the prio-0 E-CAN frames of the chapter-11 trace (#1, #58).
TEST(FrameClassifier, AnUnmarkedFrameOfPriorityZeroStaysCs2) {
    const BusProfile station = BusProfile::centralStation();
    EXPECT_EQ(classify(CanFrame::extendedFrame(0x00080201, Payload), station), Protocol::Cs2);
    const std::uint8_t ecan[] = {0x03, 0x06, 0x71, 0x66};
    EXPECT_EQ(classify(CanFrame::extendedFrame(0x01000106, ecan), station), Protocol::Cs2);
    EXPECT_EQ(classify(CanFrame::standard(0x380, {}), station), Protocol::Foreign) << "M-CAN is 29-bit only";
}

TEST(FrameClassifier, ABusWithoutMcanReadsAnMs1FrameAsCs2AndABusWithOnlyMcanCallsCs2Foreign) {
    const std::uint8_t poll[] = {0x00, 0x00, 0x00, 0x2A};
    EXPECT_EQ(classify(CanFrame::extendedFrame(0x0C0007AB, poll), BusProfile{Protocol::Cs2}), Protocol::Cs2);
    const BusProfile handheldsOnly{Protocol::Mcan};
    EXPECT_EQ(classify(CanFrame::extendedFrame(0x0C0007AB, poll), handheldsOnly), Protocol::Mcan);
    EXPECT_EQ(classify(CanFrame::extendedFrame(0x00004711, Payload), handheldsOnly), Protocol::Foreign);
}

} // namespace
} // namespace stellwerk::busreading::test
