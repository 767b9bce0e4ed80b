#include "cs2/Header.h"

#include <gtest/gtest.h>

using stellwerk::can::CanFrame;

// Field notes, "Framing": prio bits 25-28, command 17-24, response bit 16, hash 0-15.
TEST(Cs2Header, IdentifierFieldsFollowTheDocumentLayout) {
    const CanFrame frame{stellwerk::cs2::makeId(3, 0x04, true, 0x4711), 6, {0, 0, 0xC0, 0x03, 0x01, 0x20}};
    EXPECT_EQ(frame.id, 0x06094711u);
    EXPECT_EQ(stellwerk::cs2::prio(frame), 3);
    EXPECT_EQ(stellwerk::cs2::command(frame), 0x04);
    EXPECT_TRUE(stellwerk::cs2::isResponse(frame));
    EXPECT_EQ(stellwerk::cs2::hash(frame), 0x4711);
}

TEST(Cs2Header, NetworkFormIsIdBigEndianThenDlcThenEightPaddedBytes) {
    const CanFrame frame{0x00084711, 6, {0, 0, 0xC0, 0x03, 0x01, 0x20, 0xEE, 0xEE}};
    const auto bytes = frame.toNetwork();
    const std::array<std::uint8_t, 13> expected{0x00, 0x08, 0x47, 0x11, 0x06, 0x00, 0x00,
                                                0xC0, 0x03, 0x01, 0x20, 0x00, 0x00};
    EXPECT_EQ(bytes, expected) << "bytes beyond the DLC must be sent as zero";
}

TEST(Cs2Header, NetworkByteZeroIsPrioShiftedLeftOrCommandHighBit) {
    // Field notes: byte 0 = prio<<1 | command>>7, byte 1 = command<<1 | response.
    const CanFrame frame{stellwerk::cs2::makeId(2, 0x85, true, 0x0300), 0, {}};
    const auto bytes = frame.toNetwork();
    EXPECT_EQ(bytes[0], (2 << 1) | (0x85 >> 7));
    EXPECT_EQ(bytes[1], std::uint8_t((0x85 << 1) | 1));
}

TEST(Cs2Header, ReadsNetworkFormBack) {
    const std::array<std::uint8_t, 13> bytes{0x00, 0x31, 0x47, 0x11, 0x08, 0x47, 0x43,
                                             0xF5, 0xDA, 0x01, 0x3E, 0x00, 0x10};
    const CanFrame frame = CanFrame::fromNetwork(bytes);
    EXPECT_EQ(frame.id, 0x00314711u);
    EXPECT_EQ(frame.dlc, 8);
    EXPECT_EQ(frame.data[0], 0x47);
    EXPECT_EQ(frame.data[7], 0x10);
    EXPECT_EQ(frame.toNetwork(), bytes);
}

TEST(Cs2Header, KeepsAnOversizedDlcFromTheNetworkSoTheDecoderCanReportIt) {
    std::array<std::uint8_t, 13> bytes{};
    bytes[4] = 12;
    const CanFrame frame = CanFrame::fromNetwork(bytes);
    EXPECT_EQ(frame.dlc, 12);
    EXPECT_EQ(frame.size(), 8u);
    EXPECT_FALSE(frame.isWellFormed());
}

TEST(Cs2Header, IdentifierAbove29BitsIsNotWellFormed) {
    std::array<std::uint8_t, 13> bytes{};
    bytes[0] = 0x20;
    EXPECT_FALSE(CanFrame::fromNetwork(bytes).isWellFormed());
}

TEST(Cs2Header, EqualityIgnoresBytesBeyondTheDlc) {
    CanFrame a{0x1234, 2, {1, 2, 3}};
    CanFrame b{0x1234, 2, {1, 2, 9}};
    EXPECT_EQ(a, b);
    b.data[1] = 7;
    EXPECT_FALSE(a == b);
}
