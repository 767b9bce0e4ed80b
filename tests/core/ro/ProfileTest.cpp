// Module profiles: the simulator's defaults (notes B5, B7; Stellwerk-defined) and the profiles refused.
#include "ro/RegisterFile.h"
#include "ro/RoProfile.h"

#include <gtest/gtest.h>

namespace stellwerk::ro {
namespace {

TEST(RoProfile, SimulatorDefaultsFromTheNotes) {
    const RoProfile profile = RoProfile::simulator(1);
    EXPECT_EQ(profile.ids, (FrameIds{0x01FE0001, 0x01FF0001, true}));
    EXPECT_EQ(profile.outputs, (RegisterBlock{0x0000, Width::Word, 16}));
    EXPECT_EQ(profile.inputs, (RegisterBlock{0x0020, Width::Word, 16}));
    EXPECT_EQ(profile.changeFlags, (RegisterBlock{0x0022, Width::Word, 16}));
    EXPECT_EQ(profile.readRequestSize, ReadRequestSize::Eight);
    EXPECT_EQ(profile.problem(), "");
}

TEST(RoProfile, UnusableProfilesSayWhy) {
    RoProfile profile = RoProfile::simulator(1);
    profile.ids.extended = false;
    EXPECT_EQ(profile.problem(), "id 0x01FE0001 does not fit a 11-bit frame");
    profile.ids = {0x700, 0x700, false};
    EXPECT_EQ(profile.problem(), "request and answer id are both 0x700");
    profile.ids = {0x700, 0x701, false};
    EXPECT_EQ(profile.problem(), "");
    profile.outputs = {0x0000, Width::Byte, 16};
    EXPECT_EQ(profile.problem(), "outputs: 16 registers do not fit a byte");
    profile.outputs = {0xFFFF, Width::Word, 16};
    EXPECT_EQ(profile.problem(), "outputs: the block runs past address 0xFFFF");
    profile.outputs = {0x0000, Width::Bit, 1};
    EXPECT_EQ(profile.problem(), "outputs: width must be byte, word or long");
}

// Notes R6 (Stellwerk's reading, the document leaves it open): a bit access addresses bit `address & 7` of
// byte `address >> 3`. R13: an access past 0xFFFF is refused, not wrapped.
TEST(RoRegisterFile, BitAccessAndTheEndOfMemory) {
    RegisterFile registers;
    ASSERT_TRUE(registers.write(13, Width::Bit, 1));
    EXPECT_EQ(registers.byteAt(1), 0x20);
    EXPECT_EQ(registers.read(0, Width::Word), 0x2000u);
    EXPECT_EQ(registers.read(13, Width::Bit), 1u);
    ASSERT_TRUE(registers.write(13, Width::Bit, 0));
    EXPECT_EQ(registers.read(0, Width::Word), 0u);

    EXPECT_TRUE(registers.write(0xFFFC, Width::Long, 0x01020304));
    EXPECT_FALSE(registers.write(0xFFFD, Width::Long, 1));
    EXPECT_EQ(registers.read(0xFFFE, Width::Long), std::nullopt);
    EXPECT_EQ(registers.read(0xFFFF, Width::Byte), 0x01u);
}

TEST(RoRegisterFile, LittleEndianHelpers) {
    std::uint8_t bytes[4] = {};
    writeLittleEndian(bytes, 0x01020304);
    EXPECT_EQ(bytes[0], 0x04);
    EXPECT_EQ(bytes[3], 0x01);
    EXPECT_EQ(readLittleEndian(bytes), 0x01020304u);
    EXPECT_EQ(readLittleEndian(std::span(bytes, 2)), 0x0304u);
}

} // namespace
} // namespace stellwerk::ro
