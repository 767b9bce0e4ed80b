#include "cs2/Hash.h"

#include <gtest/gtest.h>

using namespace stellwerk::cs2;

// Document 1.2.4: high word XOR low word, then bits 7..9 = 0b110.
TEST(Hash, IsHighXorLowWithTheCs2Marker) {
    const std::uint32_t uid = 0x43533208;
    const std::uint16_t x = 0x4353 ^ 0x3208; // 0x715B
    const std::uint16_t hash = hashFromUid(uid);
    EXPECT_TRUE(hasCs2Marker(hash));
    EXPECT_EQ(hash & 0x7F, x & 0x7F);
    EXPECT_EQ(hash >> 10, (x >> 7) & 0x3F);
    EXPECT_EQ(hash, ((x << 3) & 0xFF00) | 0x0300 | (x & 0x7F)) << "the field notes' common implementation";
}

TEST(Hash, EveryUidGivesAMarkedHash) {
    for (std::uint32_t uid = 0; uid < 200000; uid += 7)
        ASSERT_TRUE(hasCs2Marker(hashFromUid(uid * 2654435761u))) << uid;
}

TEST(Hash, MarkerDetection) {
    EXPECT_TRUE(hasCs2Marker(0x4711));  // the document's example hash
    EXPECT_FALSE(hasCs2Marker(0x0000)); // an MS2 answering a stream
    EXPECT_FALSE(hasCs2Marker(0x0080));
}

// Document 1.2.4: a packet number hides bits 7..9, leaving 8192 values.
TEST(Hash, PacketNumbersSkipTheMarkerBits) {
    EXPECT_EQ(hashFromPacketNumber(1), 0x0301);
    EXPECT_EQ(packetNumberFromHash(0x0301), 1);
    EXPECT_EQ(hashFromPacketNumber(127), 0x037F);
    EXPECT_EQ(hashFromPacketNumber(128), 0x0700);
    for (std::uint16_t packet = 0; packet < 8192; ++packet) {
        const auto hash = hashFromPacketNumber(packet);
        ASSERT_TRUE(hasCs2Marker(hash));
        ASSERT_EQ(packetNumberFromHash(hash), packet);
    }
}

TEST(HashGuard, ForeignCommandWithOurHashIsACollision) {
    HashGuard guard(0x43533208);
    const std::uint16_t own = guard.hash();
    EXPECT_TRUE(guard.observe(CanFrame{stellwerk::cs2::makeId(0, 0x04, false, own), 4, {}}));
    EXPECT_FALSE(
        guard.observe(CanFrame{stellwerk::cs2::makeId(0, 0x04, false, std::uint16_t(own ^ 0x0400)), 4, {}}));
}

TEST(HashGuard, ResponsesAndStreamFramesWithOurHashAreNoCollision) {
    HashGuard guard(0x43533208);
    const std::uint16_t own = guard.hash();
    EXPECT_FALSE(guard.observe(CanFrame{stellwerk::cs2::makeId(0, 0x04, true, own), 6, {}}))
        << "an answer to us";
    EXPECT_FALSE(guard.observe(CanFrame{stellwerk::cs2::makeId(0, 0x21, false, own), 8, {}}))
        << "our config stream";
}

TEST(HashGuard, NewHashAvoidsEveryHashSeenOnTheBus) {
    HashGuard guard(0x12345678);
    std::vector<std::uint16_t> seen;
    for (std::uint32_t uid = 1; uid < 3000; ++uid) {
        const auto h = hashFromUid(uid * 0x01000193u);
        seen.push_back(h);
        guard.observe(CanFrame{stellwerk::cs2::makeId(0, 0x18, false, h), 0, {}});
    }
    const std::uint16_t old = guard.hash();
    const std::uint16_t fresh = guard.chooseNewHash();
    EXPECT_NE(fresh, old);
    EXPECT_TRUE(hasCs2Marker(fresh));
    for (auto h : seen)
        ASSERT_NE(fresh, h);
}

TEST(HashGuard, PacketNumbersInStreamsAreNeitherCollisionsNorSeenHashes) {
    HashGuard guard(0x00000001); // x = 1: hash 0x0301, the same as packet number 1
    ASSERT_EQ(guard.hash(), hashFromPacketNumber(1));
    EXPECT_FALSE(guard.observe(CanFrame{stellwerk::cs2::makeId(0, 0x1D, true, 0x0301), 8, {}}))
        << "status data packet";
    EXPECT_FALSE(guard.observe(CanFrame{stellwerk::cs2::makeId(0, 0x1B, false, 0x0301), 8, {}}))
        << "bootloader block";
    EXPECT_TRUE(guard.observe(CanFrame{stellwerk::cs2::makeId(0, 0x1B, false, 0x0301), 5, {}}))
        << "bootloader command";
}
