#include "can/FrameText.h"

#include <gtest/gtest.h>

using namespace stellwerk::can;

namespace {

ParsedFrame parsed(std::string_view text) {
    const auto result = parseFrame(text);
    EXPECT_TRUE(result.hasValue()) << text << ": " << (result ? "" : result.error());
    return result ? *result : ParsedFrame{};
}

std::string errorOf(std::string_view text) {
    const auto result = parseFrame(text);
    EXPECT_FALSE(result.hasValue()) << text;
    return result ? std::string() : result.error();
}

const CanFrame Stop{0x00004711, 5, {0, 0, 0, 0, 0}};

} // namespace

TEST(FrameText, DocumentNotation) {
    const auto p = parsed("00004711 5 00 00 00 00 00");
    EXPECT_EQ(p.notation, FrameNotation::Document);
    EXPECT_EQ(p.frame, Stop);
}

TEST(FrameText, DocumentNotationWithTrailingDescription) {
    EXPECT_EQ(parsed("00004711 5 00 00 00 00 00 Stopp an alle").frame, Stop);
    EXPECT_EQ(parsed("  00004711 5 00 00 00 48 03   Lok Nothalt MM2 72").frame.data[4], 0x03);
}

TEST(FrameText, CandumpCompactAndLogForms) {
    EXPECT_EQ(parsed("00004711#0000000000").frame, Stop);
    const auto log = parsed("(1700000000.123456) can0 00004711#0000000000");
    EXPECT_EQ(log.notation, FrameNotation::Candump);
    EXPECT_EQ(log.frame, Stop);
    EXPECT_EQ(parsed("vcan0 00304711#").frame.dlc, 0);
}

TEST(FrameText, BracketedScreenAndLogForms) {
    EXPECT_EQ(parsed("  can0  00004711   [5]  00 00 00 00 00").frame, Stop);
    const auto logged =
        parsed("12:09:19.884   ->TCP>CAN    CANID 0x420300   [7] 00 00 00 5f 21 70 7b(00)  ..._!p{.");
    EXPECT_EQ(logged.notation, FrameNotation::Bracketed);
    EXPECT_EQ(logged.frame.id, 0x00420300u);
    EXPECT_EQ(logged.frame.dlc, 7);
    EXPECT_EQ(logged.frame.data[6], 0x7B);
}

TEST(FrameText, NetworkFormAsOneOrThirteenTokens) {
    const auto one = parsed("00004711050000000000000000");
    EXPECT_EQ(one.notation, FrameNotation::Network);
    EXPECT_EQ(one.frame, Stop);
    EXPECT_EQ(parsed("00 00 47 11 05 00 00 00 00 00 00 00 00").frame, Stop);
}

TEST(FrameText, FormatsAllThreeNotations) {
    const CanFrame speed{0x00084711, 6, {0x00, 0x00, 0xC0, 0x03, 0x01, 0x20}};
    EXPECT_EQ(formatDocument(speed), "00084711 6 00 00 C0 03 01 20");
    EXPECT_EQ(formatCandump(speed), "00084711#0000C0030120");
    EXPECT_EQ(formatNetwork(speed), "00084711060000C00301200000");
    EXPECT_EQ(formatDocument(CanFrame{0x00304711, 0, {}}), "00304711 0");
    for (const auto& text : {formatDocument(speed), formatCandump(speed), formatNetwork(speed)})
        EXPECT_EQ(parsed(text).frame, speed) << text;
}

TEST(FrameText, OversizedDlcParsesSoTheDecoderCanReportIt) {
    EXPECT_EQ(parsed("00004711 9 00 00 00 00 00 00 00 00").frame.dlc, 9);
}

// Issue 32: "00164711 9 00" was reported as "DLC 9 announces 8 data bytes, only 1 given", which asks for
// bytes no frame can carry. The DLC is what is wrong, in the document notation and the bracketed one.
TEST(FrameText, ADlcAboveEightWithFewerBytesSaysTheDlcIsWrong) {
    EXPECT_EQ(errorOf("00164711 9 00"), "DLC 9 is above 8: a CAN frame has at most 8 data bytes (1 given)");
    EXPECT_EQ(errorOf("00164711 15"), "DLC 15 is above 8: a CAN frame has at most 8 data bytes (0 given)");
    EXPECT_EQ(errorOf("can0 00164711 [12] 00 11"),
              "DLC 12 is above 8: a CAN frame has at most 8 data bytes (2 given)");
    EXPECT_EQ(errorOf("00164711 9 00 x"),
              "DLC 9 is above 8: a CAN frame has at most 8 data bytes (1 given) before 'x'");
}

// Issue 11 (found by fuzzing): the network form accepted a DLC byte of 16..255, and `decode` then
// printed a frame it could not read back. Its data is padded to eight bytes: more cannot be written.
TEST(FrameText, NetworkFormRefusesADlcAboveEight) {
    EXPECT_EQ(errorOf("00004711100000000000000000"),
              "the network form's DLC byte (digits 9-10) is 16; a CAN frame has at most 8 data bytes");
    EXPECT_EQ(errorOf("00 00 47 11 09 00 00 00 00 00 00 00 00"),
              "the network form's DLC byte (digits 9-10) is 9; a CAN frame has at most 8 data bytes");
    EXPECT_EQ(errorOf("FFFFFFFF000000000000000000"), "identifier FFFFFFFF does not fit in 29 bits");
    EXPECT_EQ(parsed("00004711080000000000000000").frame.dlc, 8);
}

TEST(FrameText, ErrorsSayWhatIsWrong) {
    EXPECT_EQ(errorOf(""), "empty line");
    EXPECT_EQ(errorOf("00004711 7 00 00 00 00 06 0A"), "DLC 7 announces 7 data bytes, only 6 given");
    EXPECT_EQ(errorOf("00004711 2 00 00 00"), "more data bytes than DLC 2 announces");
    EXPECT_EQ(errorOf("xyz 5"), "'xyz' is not a hexadecimal CAN identifier");
    EXPECT_EQ(errorOf("00004711 x 00"), "'x' is not a DLC of 0..15");
    EXPECT_EQ(errorOf("00004711 1 0G"), "data byte '0G' is not two hex digits");
    EXPECT_EQ(errorOf("FFFFFFFF 0"), "identifier FFFFFFFF does not fit in 29 bits");
    EXPECT_EQ(errorOf("00004711#R"), "remote frames (#R) are not used by the CS2 protocol");
    EXPECT_EQ(errorOf("00004711##1"), "CAN FD frames (##) do not occur on a CS2 bus");
    EXPECT_EQ(errorOf("00004711#000"), "candump data '000' is not a sequence of hex bytes");
    EXPECT_EQ(errorOf("00004711#000000000000000000"), "candump data has 9 bytes; a CAN frame has at most 8");
    EXPECT_EQ(errorOf("00004711"), "'00004711' needs a DLC after it (document notation: ID DLC BYTES...)");
}
