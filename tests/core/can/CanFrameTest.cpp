// The protocol-neutral frame: both identifier widths, well-formedness per width, and the format as part of
// a frame's identity.

#include "can/CanFrame.h"

#include <gtest/gtest.h>

namespace stellwerk::can::test {
namespace {

const std::uint8_t Payload[] = {0x11, 0x22, 0x33};

TEST(CanFrame, StandardFrameHoldsAnElevenBitIdentifier) {
    const CanFrame frame = CanFrame::standard(0x7FF, Payload);
    EXPECT_FALSE(frame.extended);
    EXPECT_EQ(frame.idMask(), 0x7FFu);
    EXPECT_EQ(frame.dlc, 3);
    EXPECT_TRUE(frame.isWellFormed());
    EXPECT_FALSE(CanFrame::standard(0x800, Payload).isWellFormed()) << "12 bits do not fit a standard id";
    EXPECT_FALSE(frame.fitsNetworkForm());
}

TEST(CanFrame, ExtendedFrameHoldsATwentyNineBitIdentifier) {
    const CanFrame frame = CanFrame::extendedFrame(0x1FFFFFFF, Payload);
    EXPECT_TRUE(frame.extended);
    EXPECT_TRUE(frame.isWellFormed());
    EXPECT_FALSE(CanFrame::extendedFrame(0x20000000, Payload).isWellFormed());
    EXPECT_TRUE(frame.fitsNetworkForm());
}

TEST(CanFrame, SameIdInTheOtherFormatIsAnotherFrame) {
    EXPECT_NE(CanFrame::standard(0x123, Payload), CanFrame::extendedFrame(0x123, Payload));
    EXPECT_EQ(CanFrame::standard(0x123, Payload), CanFrame::standard(0x123, Payload));
}

TEST(CanFrame, PayloadBeyondEightBytesIsCut) {
    const std::uint8_t nine[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
    const CanFrame frame = CanFrame::standard(0x10, nine);
    EXPECT_EQ(frame.dlc, 8);
    EXPECT_EQ(frame.payload().back(), 8);
}

TEST(CanFrame, NetworkFormReadsBackAsAnExtendedFrame) {
    const CanFrame frame = CanFrame::extendedFrame(0x00000123, Payload);
    const auto bytes = frame.toNetwork();
    EXPECT_EQ(CanFrame::fromNetwork(bytes), frame);
    EXPECT_TRUE(CanFrame::fromNetwork(bytes).extended);
}

} // namespace
} // namespace stellwerk::can::test
