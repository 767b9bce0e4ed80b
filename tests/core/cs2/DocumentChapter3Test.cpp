// The examples of Märklin's CS2 CAN protocol document (shared/seeds/003_e81750172fa08e9b.txt) in chapter 3
// (loco management: discovery, mfx bind and verify, speed, direction, functions, CV read and write), decoded
// through the typed API, checked against the meaning the document gives them, and encoded back to the same
// bytes. Sections that print no example frame get frames built from the section's format table (the test says
// so).
//
// Example lines are quoted as the document prints them, comment included (parseFrame takes text after
// the data bytes as a comment). All frames use the document's hash 0x4711 unless a test says otherwise.

#include "DocumentExamplesSupport.h"
#include "can/FrameText.h"
#include "cs2/Codec.h"
#include "cs2/Crc16.h"
#include "cs2/Fields.h"
#include "cs2/FrameReport.h"
#include "cs2/Hash.h"
#include "cs2/Header.h"
#include "cs2/LocId.h"
#include "cs2/Messages.h"
#include "cs2/SpeedSteps.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <gtest/gtest.h>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::cs2 {
namespace {

using test::contains;
using test::decodeAs;
using test::described;
using test::expectRefused;
using test::expectRoundTrip;
using test::frame;
using test::frameText;

// ===== 3.1 Loco discovery =========================================================================

TEST(Document_3_1_LocoDiscovery, FullMfxDiscoveryCycle) {
    // "00024711 1 20  Voller mfx Discoveryzyklus": DLC 1, protocol id 0x20 = 32.
    Message envelope;
    const auto discovery = decodeAs<LocoDiscovery>("00024711 1 20", &envelope);
    EXPECT_FALSE(discovery.uid.has_value());
    EXPECT_EQ(discovery.range, 32);
    EXPECT_FALSE(discovery.ask.has_value());
    EXPECT_FALSE(envelope.response);
    EXPECT_EQ(described("00024711 1 20", "mode"), "mfx-discovery-cycle");
    expectRoundTrip("00024711 1 20");
}

TEST(Document_3_1_LocoDiscovery, Range0MfxDiscovery) {
    // "00024711 5 FF FF FF FF 00  Range 0 MFX Discovery": range 0 forces a re-registration.
    const auto discovery = decodeAs<LocoDiscovery>("00024711 5 FF FF FF FF 00");
    EXPECT_EQ(discovery.uid, 0xFFFFFFFFu);
    EXPECT_EQ(discovery.range, 0);
    EXPECT_FALSE(discovery.ask.has_value());
    EXPECT_EQ(described("00024711 5 FF FF FF FF 00", "mode"), "mfx-forced-registration");
    expectRoundTrip("00024711 5 FF FF FF FF 00");
}

TEST(Document_3_1_LocoDiscovery, Mm2Discovery) {
    // "00024711 1 21  MM2 Discovery": 0x21 = 33, MM2 20 kHz on the programming track.
    const auto discovery = decodeAs<LocoDiscovery>("00024711 1 21");
    EXPECT_FALSE(discovery.uid.has_value());
    EXPECT_EQ(discovery.range, 33);
    EXPECT_EQ(described("00024711 1 21", "mode"), "mm2-20khz");
    expectRoundTrip("00024711 1 21");
}

TEST(Document_3_1_LocoDiscovery, FormsByDlc) {
    // Form 1, DLC 0: all protocols (also the negative answer).
    const auto all = decodeAs<LocoDiscovery>("00024711 0");
    EXPECT_FALSE(all.uid.has_value());
    EXPECT_FALSE(all.range.has_value());
    EXPECT_EQ(described("00024711 0", "mode"), "all-protocols");
    expectRoundTrip("00024711 0");
    // Positive answer DLC 5 with the address found, and the debug answer DLC 6 with the ASK ratio.
    Message envelope;
    const auto found = decodeAs<LocoDiscovery>("00034711 5 FF FA 8C 43 20", &envelope);
    EXPECT_TRUE(envelope.response);
    EXPECT_EQ(found.uid, 0xFFFA8C43u);
    EXPECT_EQ(found.range, 32);
    const auto debug = decodeAs<LocoDiscovery>("00034711 6 FF FA 8C 43 20 D1");
    EXPECT_EQ(debug.uid, 0xFFFA8C43u);
    EXPECT_EQ(debug.range, 32);
    EXPECT_EQ(debug.ask, 0xD1);
    expectRoundTrip("00034711 5 FF FA 8C 43 20");
    expectRoundTrip("00034711 6 FF FA 8C 43 20 D1");
    expectRefused("00024711 2 20 00", DecodeErrorKind::UnexpectedLength);
}

TEST(Document_3_1_LocoDiscovery, RangeAndProtocolTable) {
    struct Row {
        std::uint8_t value;
        std::string_view mode;
    };
    const Row rows[] = {
        {0, "mfx-forced-registration"},
        {1, "mfx-programming-track"},
        {32, "mfx-programming-track"},
        {33, "mm2-20khz"},
        {34, "mm2-40khz"},
        {35, "dcc-short-address"},
        {36, "dcc-long-address"},
        {37, "dcc-search"},
        {38, "sx1-read-address"},
        {39, "sx1-search"},
        {64, "mfx-main-track"},
        {96, "mfx-main-track"},
        {98, "invalid-on-main-track"},
        {99, "invalid-on-main-track"},
        {100, "invalid-on-main-track"},
        {101, "invalid-on-main-track"},
        {102, "invalid-on-main-track"},
    };
    for (const auto& row : rows) {
        const std::string text = frameText("00024711", {0xFF, 0xFF, 0xFF, 0xFF, row.value});
        SCOPED_TRACE(text);
        EXPECT_EQ(decodeAs<LocoDiscovery>(text).range, row.value);
        EXPECT_EQ(described(text, "mode"), row.mode);
        expectRoundTrip(text);
    }
    // Values the table does not list.
    for (std::uint8_t value : {40, 63, 97, 103, 255})
        expectRefused(frameText("00024711", {value}), DecodeErrorKind::ReservedValue);
}

// ===== 3.2 mfx bind ===============================================================================

TEST(Document_3_2_MfxBind, BindUidToSid5) {
    // "00044711 6 FF FA 8C 43 00 05  Bind UID: FF FA 8C 43 auf SID: 05"
    Message envelope;
    const auto bind = decodeAs<MfxBind>("00044711 6 FF FA 8C 43 00 05", &envelope);
    EXPECT_EQ(bind.mfxUid, 0xFFFA8C43u);
    EXPECT_EQ(bind.sid, 5);
    EXPECT_FALSE(envelope.response);
    expectRoundTrip("00044711 6 FF FA 8C 43 00 05");
}

TEST(Document_3_2_MfxBind, Answer) {
    // "00054711 6 FF FA 8C 43 00 05  Antwort": the same bytes with the response bit.
    Message envelope;
    const auto bind = decodeAs<MfxBind>("00054711 6 FF FA 8C 43 00 05", &envelope);
    EXPECT_EQ(bind.mfxUid, 0xFFFA8C43u);
    EXPECT_EQ(bind.sid, 5);
    EXPECT_TRUE(envelope.response);
    expectRoundTrip("00054711 6 FF FA 8C 43 00 05");
}

// ===== 3.3 mfx verify =============================================================================

TEST(Document_3_3_MfxVerify, VerifyUidOnSid5) {
    Message envelope;
    const auto verify =
        decodeAs<MfxVerify>("00064711 6 FF FA 8C 43 00 05 Verify FF FA 8C 43 auf SID 05", &envelope);
    EXPECT_EQ(verify.mfxUid, 0xFFFA8C43u);
    EXPECT_EQ(verify.sid, 5);
    EXPECT_FALSE(verify.ask.has_value());
    EXPECT_FALSE(envelope.response);
    expectRoundTrip("00064711 6 FF FA 8C 43 00 05 Verify FF FA 8C 43 auf SID 05");
}

TEST(Document_3_3_MfxVerify, NegativeAnswer) {
    // "00074711 6 FF FA 8C 43 00 00  Antwort negativ": SID set to 0x0000.
    Message envelope;
    const auto verify = decodeAs<MfxVerify>("00074711 6 FF FA 8C 43 00 00 Antwort negativ", &envelope);
    EXPECT_EQ(verify.mfxUid, 0xFFFA8C43u);
    EXPECT_EQ(verify.sid, 0);
    EXPECT_FALSE(verify.ask.has_value());
    EXPECT_TRUE(envelope.response);
    expectRoundTrip("00074711 6 FF FA 8C 43 00 00 Antwort negativ");
}

TEST(Document_3_3_MfxVerify, PositiveAnswerWithAskD1) {
    // "00074711 7 FF FA 8C 43 00 05 D1  Antwort positiv mit ASK-Verhältnis 0xD1"
    Message envelope;
    const auto verify = decodeAs<MfxVerify>(
        "00074711 7 FF FA 8C 43 00 05 D1 Antwort positiv mit ASK-Verhältnis 0xD1", &envelope);
    EXPECT_EQ(verify.mfxUid, 0xFFFA8C43u);
    EXPECT_EQ(verify.sid, 5);
    EXPECT_EQ(verify.ask, 0xD1);
    EXPECT_TRUE(envelope.response);
    expectRoundTrip("00074711 7 FF FA 8C 43 00 05 D1 Antwort positiv mit ASK-Verhältnis 0xD1");
}

// ===== 3.4 Loco speed =============================================================================

TEST(Document_3_4_LocoSpeed, Sx1Address3Speed800) {
    // "00084711 6 00 00 08 03 03 20  Lok Geschwindigkeit SX1 Adr 3, V=0x0320=800"
    Message envelope;
    const auto speed = decodeAs<LocoSpeed>(
        "00084711 6 00 00 08 03 03 20 Lok Geschwindigkeit SX1 Adr 3, V=0x0320=800 von 1024", &envelope);
    EXPECT_EQ(speed.loco.value(), 0x00000803u);
    EXPECT_EQ(speed.loco.protocol(), Protocol::Sx1);
    EXPECT_EQ(speed.loco.address(), 3u);
    EXPECT_EQ(speed.speed, 800);
    EXPECT_FALSE(envelope.response);
    expectRoundTrip("00084711 6 00 00 08 03 03 20 Lok Geschwindigkeit SX1 Adr 3, V=0x0320=800 von 1024");
}

TEST(Document_3_4_LocoSpeed, Sx1Address3Speed160) {
    // The document's comment says "V=0x00A0=10"; 0x00A0 is 160.
    const auto speed = decodeAs<LocoSpeed>(
        "00084711 6 00 00 08 03 00 A0 Lok Geschwindigkeit SX1 Adr 3, V=0x00A0=10 von 1024");
    EXPECT_EQ(speed.loco.value(), 0x00000803u);
    EXPECT_EQ(speed.loco.protocol(), Protocol::Sx1);
    EXPECT_EQ(speed.loco.address(), 3u);
    EXPECT_EQ(speed.speed, 160);
    expectRoundTrip("00084711 6 00 00 08 03 00 A0 Lok Geschwindigkeit SX1 Adr 3, V=0x00A0=10 von 1024");
}

TEST(Document_3_4_LocoSpeed, MfxAddress1Speed800) {
    const auto speed = decodeAs<LocoSpeed>(
        "00084711 6 00 00 40 01 03 20 Lok Geschwindigkeit mfx Adr 1, V=0x0320=800 von 1024");
    EXPECT_EQ(speed.loco.value(), 0x00004001u);
    EXPECT_EQ(speed.loco.protocol(), Protocol::Mfx);
    EXPECT_EQ(speed.loco.address(), 1u);
    EXPECT_EQ(speed.speed, 800);
    expectRoundTrip("00084711 6 00 00 40 01 03 20 Lok Geschwindigkeit mfx Adr 1, V=0x0320=800 von 1024");
}

TEST(Document_3_4_LocoSpeed, DccAddress3Speed288) {
    // The document gives no value for this line; 0x0120 = 288.
    const auto speed = decodeAs<LocoSpeed>("00084711 6 00 00 C0 03 01 20 Lok Geschwindigkeit DCC Adr 3");
    EXPECT_EQ(speed.loco.value(), 0x0000C003u);
    EXPECT_EQ(speed.loco.protocol(), Protocol::Dcc);
    EXPECT_EQ(speed.loco.address(), 3u);
    EXPECT_EQ(speed.speed, 288);
    const std::string report = FrameReport(frame("00084711 6 00 00 C0 03 01 20")).text();
    EXPECT_TRUE(contains(report, "loco.speed")) << report;
    EXPECT_TRUE(contains(report, "locId=0xC003 protocol=dcc address=3 speed=288")) << report;
    expectRoundTrip("00084711 6 00 00 C0 03 01 20 Lok Geschwindigkeit DCC Adr 3");
}

TEST(Document_3_4_LocoSpeed, DccAddress3Speed160) {
    const auto speed = decodeAs<LocoSpeed>("00084711 6 00 00 C0 03 00 A0 Lok Geschwindigkeit DCC Adr 3");
    EXPECT_EQ(speed.loco.value(), 0x0000C003u);
    EXPECT_EQ(speed.loco.protocol(), Protocol::Dcc);
    EXPECT_EQ(speed.loco.address(), 3u);
    EXPECT_EQ(speed.speed, 160);
    expectRoundTrip("00084711 6 00 00 C0 03 00 A0 Lok Geschwindigkeit DCC Adr 3");
}

TEST(Document_3_4_LocoSpeed, QueryAndAnswer) {
    // DLC 4: query; the answer has the set form, or repeats the query when the loco is unknown.
    Message envelope;
    const auto query = decodeAs<LocoSpeed>("00084711 4 00 00 C0 03", &envelope);
    EXPECT_EQ(query.loco.value(), 0x0000C003u);
    EXPECT_FALSE(query.speed.has_value());
    EXPECT_FALSE(envelope.response);
    const auto answer = decodeAs<LocoSpeed>("00094711 6 00 00 C0 03 01 20", &envelope);
    EXPECT_EQ(answer.speed, 288);
    EXPECT_TRUE(envelope.response);
    const auto unknown = decodeAs<LocoSpeed>("00094711 4 00 00 C0 03", &envelope);
    EXPECT_FALSE(unknown.speed.has_value());
    EXPECT_TRUE(envelope.response);
    expectRoundTrip("00084711 4 00 00 C0 03");
    expectRoundTrip("00094711 6 00 00 C0 03 01 20");
    expectRoundTrip("00094711 4 00 00 C0 03");
    expectRefused("00084711 5 00 00 C0 03 01", DecodeErrorKind::UnexpectedLength);
}

TEST(Document_3_4_LocoSpeed, TenBitRange) {
    // "0 bis 1024 (10 Bit)": ten bits end at 1023, which 1.3.3 names as the top value; 1024 is refused.
    EXPECT_EQ(decodeAs<LocoSpeed>("00084711 6 00 00 C0 03 03 E8").speed, 1000);
    EXPECT_EQ(decodeAs<LocoSpeed>("00084711 6 00 00 C0 03 03 FF").speed, 1023);
    expectRefused("00084711 6 00 00 C0 03 04 00", DecodeErrorKind::ReservedValue);
}

// ===== 3.5 Loco direction (no example in the document; value table) ==============================

TEST(Document_3_5_LocoDirection, DirectionValueTable) {
    struct Row {
        std::uint8_t value;
        std::string_view name;
    };
    // 0 keep, 1 forward, 2 backward, 3 toggle, "Rest: Richtung bleibt".
    const Row rows[] = {{0, "keep"},   {1, "forward"}, {2, "backward"},
                        {3, "toggle"}, {4, "keep"},    {0xFF, "keep"}};
    for (const auto& row : rows) {
        const std::string text = frameText("000A4711", {0x00, 0x00, 0xC0, 0x03, row.value});
        SCOPED_TRACE(text);
        const auto direction = decodeAs<LocoDirection>(text);
        EXPECT_EQ(direction.loco.value(), 0x0000C003u);
        EXPECT_EQ(direction.direction, row.value);
        EXPECT_EQ(described(text, "direction"), row.name);
        expectRoundTrip(text);
    }
    EXPECT_EQ(std::uint8_t(Direction::Keep), 0);
    EXPECT_EQ(std::uint8_t(Direction::Forward), 1);
    EXPECT_EQ(std::uint8_t(Direction::Backward), 2);
    EXPECT_EQ(std::uint8_t(Direction::Toggle), 3);
}

TEST(Document_3_5_LocoDirection, QueryAndAnswer) {
    // DLC 4 asks; the answer always has the set form (DLC 5), even for an unknown loco.
    Message envelope;
    const auto query = decodeAs<LocoDirection>("000A4711 4 00 00 40 05", &envelope);
    EXPECT_EQ(query.loco.value(), 0x00004005u);
    EXPECT_FALSE(query.direction.has_value());
    EXPECT_FALSE(envelope.response);
    const auto answer = decodeAs<LocoDirection>("000B4711 5 00 00 40 05 02", &envelope);
    EXPECT_EQ(answer.direction, std::uint8_t(Direction::Backward));
    EXPECT_TRUE(envelope.response);
    expectRoundTrip("000A4711 4 00 00 40 05");
    expectRoundTrip("000B4711 5 00 00 40 05 02");
    expectRefused("000A4711 6 00 00 40 05 02 00", DecodeErrorKind::UnexpectedLength);
}

// ===== 3.6 Loco function (no example in the document; frames built from the format table) =========

TEST(Document_3_6_LocoFunction, QueryF0) {
    const auto query = decodeAs<LocoFunction>("000C4711 5 00 00 C0 03 00");
    EXPECT_EQ(query.loco.value(), 0x0000C003u);
    EXPECT_EQ(query.function, 0);
    EXPECT_FALSE(query.value.has_value());
    EXPECT_FALSE(query.functionValue.has_value());
    expectRoundTrip("000C4711 5 00 00 C0 03 00");
}

TEST(Document_3_6_LocoFunction, SwitchOnAndOff) {
    // Value 0 = off, 1..31 = on (or a dimming value where the protocol has one); functions F0..F31.
    const auto on = decodeAs<LocoFunction>("000C4711 6 00 00 00 48 01 01");
    EXPECT_EQ(on.loco.address(), 72u);
    EXPECT_EQ(on.function, 1);
    EXPECT_EQ(on.value, 1);
    EXPECT_EQ(decodeAs<LocoFunction>("000C4711 6 00 00 00 48 01 00").value, 0);
    const auto dimmed = decodeAs<LocoFunction>("000D4711 6 00 00 40 05 1F 1F");
    EXPECT_EQ(dimmed.function, 31);
    EXPECT_EQ(dimmed.value, 31);
    expectRoundTrip("000C4711 6 00 00 00 48 01 01");
    expectRoundTrip("000C4711 6 00 00 00 48 01 00");
    expectRoundTrip("000D4711 6 00 00 40 05 1F 1F");
    expectRefused("000C4711 6 00 00 40 05 20 01", DecodeErrorKind::ReservedValue); // F32
}

TEST(Document_3_6_LocoFunction, FunctionValueForm) {
    // DLC 8: as DLC 6 plus a 16-bit function value for the decoder.
    const auto special = decodeAs<LocoFunction>("000C4711 8 00 00 40 05 02 01 00 80");
    EXPECT_EQ(special.loco.value(), 0x00004005u);
    EXPECT_EQ(special.function, 2);
    EXPECT_EQ(special.value, 1);
    EXPECT_EQ(special.functionValue, 0x0080);
    expectRoundTrip("000C4711 8 00 00 40 05 02 01 00 80");
    expectRefused("000C4711 7 00 00 40 05 02 01 00", DecodeErrorKind::UnexpectedLength);
}

// ===== 3.7 Read config (no example in the document; frames built from the format table) ==========

TEST(Document_3_7_ConfigRead, DccReadCv1) {
    Message envelope;
    const auto read = decodeAs<ConfigRead>("000E4711 7 00 00 C0 03 00 01 01", &envelope);
    EXPECT_EQ(read.loco.value(), 0x0000C003u);
    EXPECT_EQ(read.cv.number, 1);
    EXPECT_EQ(read.cv.index, 0);
    EXPECT_EQ(read.count, 1);
    EXPECT_FALSE(read.value.has_value());
    EXPECT_FALSE(envelope.response);
    expectRoundTrip("000E4711 7 00 00 C0 03 00 01 01");
}

TEST(Document_3_7_ConfigRead, CountZeroReads256Bytes) {
    // "Wert 00 für Anzahl liest 256 Bytes aus dem Decoder": the count stays 0 on the wire.
    const auto read = decodeAs<ConfigRead>("000E4711 7 00 00 C0 03 00 01 00");
    EXPECT_EQ(read.count, 0);
    expectRoundTrip("000E4711 7 00 00 C0 03 00 01 00");
}

TEST(Document_3_7_ConfigRead, AnswerCarriesTheValue) {
    // "Platzhalter Anzahl beinhaltet nun den gelesenen Wert."
    Message envelope;
    const auto answer = decodeAs<ConfigRead>("000F4711 7 00 00 C0 03 00 01 03", &envelope);
    EXPECT_TRUE(envelope.response);
    EXPECT_EQ(answer.loco.value(), 0x0000C003u);
    EXPECT_EQ(answer.cv.number, 1);
    EXPECT_EQ(answer.value, 3);
    EXPECT_FALSE(answer.count.has_value());
    EXPECT_EQ(described("000F4711 7 00 00 C0 03 00 01 03", "value"), "3");
    expectRoundTrip("000F4711 7 00 00 C0 03 00 01 03");
}

TEST(Document_3_7_ConfigRead, FailedAnswerHasNoValue) {
    // "Konnte kein Wert ausgelesen werden, so wird ein Frame mit DLC=6 und fehlendem D-Byte 6 ausgegeben."
    Message envelope;
    const auto failed = decodeAs<ConfigRead>("000F4711 6 00 00 C0 03 00 01", &envelope);
    EXPECT_TRUE(envelope.response);
    EXPECT_EQ(failed.cv.number, 1);
    EXPECT_FALSE(failed.value.has_value());
    EXPECT_FALSE(failed.count.has_value());
    expectRoundTrip("000F4711 6 00 00 C0 03 00 01");
    // Without the response bit DLC 6 is no form of the command.
    expectRefused("000E4711 6 00 00 C0 03 00 01", DecodeErrorKind::UnexpectedLength);
}

TEST(Document_3_7_ConfigRead, CvIndexAndNumberPacking) {
    // CV index in the 6 high bits of D-Byte 4; CV number in D-Byte 5 and the 2 low bits of D-Byte 4.
    struct Row {
        std::uint8_t byte4;
        std::uint8_t byte5;
        std::uint8_t index;
        std::uint16_t number;
    };
    const Row rows[] = {{0x00, 0x01, 0, 1},   {0x03, 0xFF, 0, 1023}, {0x04, 0x00, 1, 0},
                        {0x05, 0x02, 1, 258}, {0xFC, 0x00, 63, 0},   {0xFF, 0xFF, 63, 1023}};
    for (const auto& row : rows) {
        const std::string text = frameText("000E4711", {0x00, 0x00, 0x40, 0x05, row.byte4, row.byte5, 0x01});
        SCOPED_TRACE(text);
        const auto read = decodeAs<ConfigRead>(text);
        EXPECT_EQ(read.cv.index, row.index);
        EXPECT_EQ(read.cv.number, row.number);
        EXPECT_EQ(CvAddress::unpack(std::uint16_t((row.byte4 << 8) | row.byte5)).number, row.number);
        EXPECT_EQ((CvAddress{row.number, row.index}.packed()), std::uint16_t((row.byte4 << 8) | row.byte5));
        EXPECT_EQ(described(text, "cvIndex"), std::to_string(row.index));
        EXPECT_EQ(described(text, "cvNumber"), std::to_string(row.number));
        expectRoundTrip(text);
    }
}

// ===== 3.8 Write config (no example in the document; frames built from the format table) =========

TEST(Document_3_8_ConfigWrite, DccProgrammingModes) {
    // The document counts bits from 1: bit 8 = 0x80 main track, bit 7 = 0x40 multi-byte, bit 6 = 0x20
    // "DCC1", bit 5 = 0x10 "DCC2". DCC1/DCC2: 00 direct, 01 register, 10 bit, 11 reserved.
    struct Row {
        std::uint8_t control;
        DccProgrammingMode mode;
        std::string_view name;
    };
    const Row rows[] = {{0x00, DccProgrammingMode::Direct, "direct"},
                        {0x10, DccProgrammingMode::Register, "register"},
                        {0x20, DccProgrammingMode::Bit, "bit"}};
    for (const auto& row : rows) {
        const std::string text =
            frameText("00104711", {0x00, 0x00, 0xC0, 0x03, 0x00, 0x01, 0x03, row.control});
        SCOPED_TRACE(text);
        const auto write = decodeAs<ConfigWrite>(text);
        EXPECT_EQ(write.loco.value(), 0x0000C003u);
        EXPECT_EQ(write.cv.number, 1);
        EXPECT_EQ(write.value, 3);
        EXPECT_EQ(write.mode(), row.mode);
        EXPECT_EQ(described(text, "mode"), row.name);
        EXPECT_EQ(described(text, "track"), "programming");
        EXPECT_EQ(described(text, "multiByte"), "false");
        expectRoundTrip(text);
    }
    expectRefused("00104711 8 00 00 C0 03 00 01 03 30", DecodeErrorKind::ReservedValue);
}

TEST(Document_3_8_ConfigWrite, MainTrackMultiByteBitProgramming) {
    // Bit programming value "1111DBBB": 0xFD sets bit 5 to 1. Control: main track, more writes follow, bit
    // mode.
    const std::string text = "00104711 8 00 00 C0 03 00 1D FD E0";
    const auto write = decodeAs<ConfigWrite>(text);
    EXPECT_EQ(write.cv.number, 29);
    EXPECT_EQ(write.value, 0xFD);
    EXPECT_EQ(write.flags & ConfigWrite::MainTrack, ConfigWrite::MainTrack);
    EXPECT_EQ(write.flags & ConfigWrite::MultiByte, ConfigWrite::MultiByte);
    EXPECT_EQ(write.mode(), DccProgrammingMode::Bit);
    EXPECT_EQ(described(text, "track"), "main");
    EXPECT_EQ(described(text, "multiByte"), "true");
    expectRoundTrip(text);
}

TEST(Document_3_8_ConfigWrite, ResultBitsInTheAnswer) {
    // In the answer bit 8 (0x80) = write confirmed by the controller, bit 7 (0x40) = verify succeeded.
    Message envelope;
    const auto both = decodeAs<ConfigWrite>("00114711 8 00 00 C0 03 00 01 03 C0", &envelope);
    EXPECT_TRUE(envelope.response);
    EXPECT_EQ(both.flags, ConfigWrite::WriteOk | ConfigWrite::VerifyOk);
    EXPECT_EQ(described("00114711 8 00 00 C0 03 00 01 03 C0", "writeOk"), "true");
    EXPECT_EQ(described("00114711 8 00 00 C0 03 00 01 03 C0", "verifyOk"), "true");
    EXPECT_EQ(described("00114711 8 00 00 C0 03 00 01 03 80", "writeOk"), "true");
    EXPECT_EQ(described("00114711 8 00 00 C0 03 00 01 03 80", "verifyOk"), "false");
    expectRoundTrip("00114711 8 00 00 C0 03 00 01 03 C0");
    expectRoundTrip("00114711 8 00 00 C0 03 00 01 03 80");
    // The request's mode bits have no meaning in an answer, so 0b11 there is no error.
    expectRoundTrip("00114711 8 00 00 C0 03 00 01 03 30");
    expectRefused("00104711 7 00 00 C0 03 00 01 03", DecodeErrorKind::TooShort);
}

} // namespace
} // namespace stellwerk::cs2
