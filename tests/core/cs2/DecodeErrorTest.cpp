// Every class of invalid input yields a typed error, never a crash or a wrong message.

#include "TestSupport.h"

#include <gtest/gtest.h>

using namespace stellwerk::cs2;
using test::frame;

namespace {

DecodeError decodeErrorOf(const CanFrame& input) {
    const auto result = decode(input);
    EXPECT_FALSE(result.hasValue()) << formatDocument(input) << " decoded as " << messageName(result->body);
    return result ? DecodeError{DecodeErrorKind::TooShort, 0, 0, {}} : result.error();
}

DecodeErrorKind kindOf(std::string_view text) {
    return decodeErrorOf(frame(text)).kind;
}

} // namespace

TEST(DecodeError, DlcAboveEightIsRejected) {
    CanFrame broken{0x00004711, 12, {0, 0, 0, 0, 0}};
    const DecodeError error = decodeErrorOf(broken);
    EXPECT_EQ(error.kind, DecodeErrorKind::DlcOutOfRange);
    EXPECT_EQ(error.dlc, 12);
    EXPECT_NE(error.message().find("DLC 12 is above 8"), std::string::npos) << error.message();
}

TEST(DecodeError, DlcAboveEightFromTheNetworkFormIsRejected) {
    std::array<std::uint8_t, 13> bytes{0x00, 0x08, 0x47, 0x11, 0x0F};
    EXPECT_EQ(decodeErrorOf(CanFrame::fromNetwork(bytes)).kind, DecodeErrorKind::DlcOutOfRange);
}

TEST(DecodeError, IdentifierBeyond29BitsIsRejected) {
    std::array<std::uint8_t, 13> bytes{0xE0, 0x08, 0x47, 0x11, 0x00};
    EXPECT_EQ(decodeErrorOf(CanFrame::fromNetwork(bytes)).kind, DecodeErrorKind::IdOutOfRange);
}

TEST(DecodeError, TooShortForItsCommand) {
    EXPECT_EQ(kindOf("00004711 4 00 00 00 00"), DecodeErrorKind::TooShort);          // system: no sub-command
    EXPECT_EQ(kindOf("00084711 2 00 00"), DecodeErrorKind::TooShort);                // speed: half a Loc-ID
    EXPECT_EQ(kindOf("000C4711 4 00 00 C0 03"), DecodeErrorKind::TooShort);          // function: no number
    EXPECT_EQ(kindOf("00044711 5 FF FA 8C 43 00"), DecodeErrorKind::TooShort);       // bind: half a SID
    EXPECT_EQ(kindOf("00104711 7 00 00 C0 03 00 01 03"), DecodeErrorKind::TooShort); // write: no ctrl byte
    EXPECT_EQ(kindOf("00164711 5 00 00 30 00 01"), DecodeErrorKind::TooShort);       // accessory: no current
    EXPECT_EQ(kindOf("00224711 3 00 01 00"), DecodeErrorKind::TooShort);    // s88 event: half a contact
    EXPECT_EQ(kindOf("003A4711 4 00 00 00 00"), DecodeErrorKind::TooShort); // statusdata: no index
    EXPECT_EQ(kindOf("00604711 4 00 01 41 31"), DecodeErrorKind::TooShort); // automation: no position
}

TEST(DecodeError, LengthThatNoFormHas) {
    EXPECT_EQ(kindOf("00084711 5 00 00 C0 03 01"), DecodeErrorKind::UnexpectedLength);
    EXPECT_EQ(kindOf("00004711 8 00 00 00 00 00 00 00 00"), DecodeErrorKind::UnexpectedLength); // stop, DLC 8
    EXPECT_EQ(kindOf("00024711 3 00 00 00"), DecodeErrorKind::UnexpectedLength);
    EXPECT_EQ(kindOf("000C4711 7 00 00 C0 03 00 01 00"), DecodeErrorKind::UnexpectedLength);
    EXPECT_EQ(kindOf("00424711 5 00 00 00 00 00"), DecodeErrorKind::UnexpectedLength); // stream: abort rule
    EXPECT_EQ(kindOf("00404711 4 6C 6F 6B 73"), DecodeErrorKind::UnexpectedLength);    // file name is 8 bytes
    EXPECT_EQ(kindOf("00304711 4 00 00 00 00"), DecodeErrorKind::UnexpectedLength);    // ping: 0 or 8
    EXPECT_EQ(kindOf("00204711 6 00 00 00 00 01 00"), DecodeErrorKind::UnexpectedLength);
}

TEST(DecodeError, ReservedValues) {
    EXPECT_EQ(kindOf("00084711 6 00 00 C0 03 04 00"), DecodeErrorKind::ReservedValue); // speed 1024
    EXPECT_EQ(kindOf("000C4711 6 00 00 C0 03 20 01"), DecodeErrorKind::ReservedValue); // F32
    EXPECT_EQ(kindOf("00024711 1 28"), DecodeErrorKind::ReservedValue);                // discovery range 40
    EXPECT_EQ(kindOf("00004711 6 00 00 00 00 08 08"), DecodeErrorKind::ReservedValue); // track protocol bit 3
    EXPECT_EQ(kindOf("00004711 6 00 00 C0 03 05 05"), DecodeErrorKind::ReservedValue); // DCC sub-protocol 5
    EXPECT_EQ(kindOf("00004711 6 00 00 00 03 05 03"), DecodeErrorKind::ReservedValue); // MM2 sub-protocol 3
    EXPECT_EQ(kindOf("00104711 8 00 00 C0 03 00 01 03 30"), DecodeErrorKind::ReservedValue); // DCC mode 0b11
    EXPECT_EQ(kindOf("00164711 6 00 00 30 00 01 20"), DecodeErrorKind::ReservedValue);       // current 32
    EXPECT_EQ(kindOf("00014711 7 43 53 32 08 0B 01 02"),
              DecodeErrorKind::ReservedValue); // ack neither 0 nor 1
}

TEST(DecodeError, MessagesNameTheCommandRuleAndLength) {
    const DecodeError error = decodeErrorOf(frame("00084711 5 00 00 C0 03 01"));
    EXPECT_EQ(error.command, 0x04);
    EXPECT_EQ(error.dlc, 5);
    EXPECT_EQ(error.message(), "unexpected length 5: loco.speed has 4 (query) or 6 data bytes");
}

// An 11-bit frame of another protocol would otherwise read as a system command (command bits 0).
TEST(DecodeError, StandardFramesAreNotCs2Frames) {
    const std::uint8_t stopLike[5] = {};
    const auto result = decode(CanFrame::standard(0x000, stopLike));
    ASSERT_FALSE(result.hasValue());
    EXPECT_EQ(result.error().kind, DecodeErrorKind::IdOutOfRange);
}

TEST(DecodeError, UnknownCommandsAreNotErrors) {
    for (std::uint8_t command : {0x09, 0x0A, 0x0D, 0x13, 0x1E, 0x31, 0x42, 0x7F, 0xFF}) {
        CanFrame input{stellwerk::cs2::makeId(0, command, false, 0x4711), 3, {1, 2, 3}};
        const auto result = decode(input);
        ASSERT_TRUE(result.hasValue()) << int(command);
        const auto& unknown = std::get<Unknown>(result->body);
        EXPECT_EQ(unknown.command, command);
        EXPECT_EQ(unknown.raw.size, 3);
        EXPECT_EQ(unknown.raw.bytes[2], 3);
    }
}

TEST(DecodeError, UnknownSystemSubcommandKeepsItsBytes) {
    const auto result =
        decode(frame("00004711 8 00 00 00 00 20 0C 1E 01")); // model time, not in the document
    ASSERT_TRUE(result.hasValue());
    const auto& unknown = std::get<Unknown>(result->body);
    EXPECT_EQ(unknown.command, 0);
    EXPECT_EQ(unknown.raw.bytes[4], 0x20);
    EXPECT_EQ(systemSubcommand(result->body), std::optional<std::uint8_t>(0x20));
}
