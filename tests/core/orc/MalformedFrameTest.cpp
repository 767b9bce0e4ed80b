// Frames in or near OpenRailCAN space that no documented form fits are refused: they decode as orc.unknown
// with a reason a person can act on, never as something else.

#include "orc/Codec.h"

#include <gtest/gtest.h>
#include <initializer_list>

using namespace stellwerk;
using namespace stellwerk::orc;

namespace {

can::CanFrame malformedFrame(std::uint32_t id, std::initializer_list<std::uint8_t> bytes) {
    return can::CanFrame::extendedFrame(id, std::span<const std::uint8_t>(bytes.begin(), bytes.size()));
}

std::string why(const can::CanFrame& f) {
    const Message message = decode(f);
    if (!std::holds_alternative<Unknown>(message))
        return "decoded as " + std::string(nameOf(message));
    return std::string(std::get<Unknown>(message).why);
}

constexpr std::uint32_t SystemCommand = 0x09000000; // prio 1, group 0x80, D=0
constexpr std::uint32_t SystemAnswer = 0x09010000;  // D=1
constexpr std::uint32_t LocoCommand = 0x11020000;
constexpr std::uint32_t LocoAnswer = 0x11030000;
constexpr std::uint32_t DecoderCommand = 0x11100000;
constexpr std::uint32_t EncoderCommand = 0x11120000;
constexpr std::uint32_t ManagementCommand = 0x19200000;
constexpr std::uint32_t FlashCommand = 0x19E00000;

} // namespace

TEST(Malformed, AllesAusWithDlc2IsRefused) {
    EXPECT_EQ(why(malformedFrame(SystemCommand, {0x00, 0x2E})),
              "Alles Aus / Alles EIN take DLC 1, 3 (Ziel-Id) or 5 (Ziel-UID)");
}

TEST(Malformed, AllesAusAsAnswerIsRefused) {
    EXPECT_EQ(why(malformedFrame(SystemAnswer, {0x00})), "Alles Aus / Alles EIN are commands (D=0)");
}

TEST(Malformed, EmptyFrameHasNoSubCommand) {
    EXPECT_EQ(why(malformedFrame(SystemCommand, {})), "no sub-command: DB1 is missing");
}

TEST(Malformed, PriorityZeroIsNeverSent) {
    EXPECT_EQ(why(malformedFrame(0x01000000, {0x00})), "priority 00 is never sent (kept for Maerklin/ESU)");
}

TEST(Malformed, UnknownGroupIsRefused) {
    EXPECT_EQ(why(malformedFrame(0x09400000, {0x00})), "a command group the document does not define");
}

TEST(Malformed, StandardFrameIsRefused) {
    const std::array<std::uint8_t, 1> data{0};
    EXPECT_EQ(why(can::CanFrame::standard(0x123, data)),
              "an 11-bit frame: OpenRailCAN uses 29-bit identifiers");
}

TEST(Malformed, DlcAbove8IsRefused) {
    can::CanFrame f = malformedFrame(SystemCommand, {0x00});
    f.dlc = 9;
    EXPECT_EQ(why(f), "DLC above 8 or identifier above 29 bits");
}

TEST(Malformed, SpeedQueryAsAnswerIsRefused) {
    EXPECT_EQ(why(malformedFrame(LocoAnswer, {0x01, 0x00, 0x48})),
              "Lok Speed 0x01 takes DLC 3 (query, D=0), 5 (Ziel-Id, speed) or 7 (Ziel-UID, speed)");
}

TEST(Malformed, FunctionValueWiderThanOneByteIsRefused) {
    EXPECT_EQ(why(malformedFrame(LocoCommand, {0x04, 0x00, 0x48, 0x01, 0x01, 0x02, 0x00})),
              "Lok Funktion 0x04: Wert is one byte (DB5); DB6-7 must be 0");
}

TEST(Malformed, DecoderSwitchWithoutPosIsRefused) {
    EXPECT_EQ(why(malformedFrame(DecoderCommand, {0x03, 0x30, 0x05})),
              "dekoder schalten takes DLC 4 (Ziel-Id, Pos)");
}

TEST(Malformed, EncoderQueryWithDlc2IsRefused) {
    EXPECT_EQ(why(malformedFrame(EncoderCommand, {0x10, 0x2E})), "enkoder Abfrage takes DLC 1 or 3 with D=0");
}

TEST(Malformed, UnknownSubCommandIsRefused) {
    EXPECT_EQ(why(malformedFrame(DecoderCommand, {0x07})), "a sub-command group 0x88 does not define");
    EXPECT_EQ(why(malformedFrame(EncoderCommand, {0x05})), "a sub-command group 0x89 does not define");
    EXPECT_EQ(why(malformedFrame(ManagementCommand, {0x09})), "a sub-command group 0x90 does not define");
}

TEST(Malformed, PingWithDlc3IsRefused) {
    EXPECT_EQ(why(malformedFrame(ManagementCommand, {0x00, 0x3A, 0x2E})),
              "Ping / Find take DLC 5 (D=0) or 7 (D=1); the bus-id assignment DLC 7");
}

TEST(Malformed, FlashDataWithDlc5IsRefused) {
    EXPECT_EQ(why(malformedFrame(FlashCommand, {0x04, 0x2E, 0x01, 0x00, 0x01})),
              "Flash Data and Checksum take DLC 8");
}

// Found by fuzz/orc_frame: DLC 8 gave five status bytes, shifted by 32 bits into a 32-bit value
// (undefined behaviour) and encoded back as four. Status 0 ... 31 fits DLC 4 to 7.
TEST(Malformed, EncoderStatusWithFiveStatusBytesIsRefused) {
    EXPECT_EQ(why(malformedFrame(EncoderCommand, {0x10, 0x2E, 0x01, 0x01, 0x02, 0x03, 0x04, 0x05})),
              "enkoder Status takes DLC 4 to 7 (status 0 ... 31)");
    EXPECT_EQ(why(malformedFrame(EncoderCommand | 0x10000, {0x10, 0x2E, 0x01, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF})),
              "enkoder Status takes DLC 4 to 7 (status 0 ... 31)");
    EXPECT_EQ(why(malformedFrame(EncoderCommand, {0x10, 0x2E, 0x01, 0x01, 0x02, 0x03, 0x04})),
              "decoded as orc.encoder.status");
}

// Found by fuzz/orc_frame: a single-function frame with DLC 8 decoded, and encoded back with DLC 7.
TEST(Malformed, LocoFunctionWithDlc8IsRefused) {
    EXPECT_EQ(why(malformedFrame(LocoCommand, {0x04, 0x00, 0x48, 0x01, 0x01, 0x00, 0x00, 0x00})),
              "Lok Funktion 0x04 takes DLC 4 (query, D=0) or 5-7 (FxNr, Wert)");
    EXPECT_EQ(why(malformedFrame(LocoAnswer, {0x04, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00})),
              "Lok Funktion 0x04 takes DLC 4 (query, D=0) or 5-7 (FxNr, Wert)");
    EXPECT_EQ(why(malformedFrame(LocoCommand, {0x04, 0x00, 0x48, 0x01, 0x01, 0x00, 0x00})),
              "decoded as orc.loco.function");
}
