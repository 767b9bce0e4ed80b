// The examples of Märklin's CS2 CAN protocol document (shared/seeds/003_e81750172fa08e9b.txt) in chapter 2
// (system commands), decoded through the typed API, checked against the meaning the document gives them, and
// encoded back to the same bytes. Sections that print no example frame get frames built from the section's
// format table (the test says so).
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
using test::frameText;

// ===== 2.1 System Stop ===========================================================================

TEST(Document_2_1_SystemStop, StopToAll) {
    // "00004711 5 00 00 00 00 00 Stopp an alle": target UID 0 addresses every track format processor.
    Message envelope;
    const auto stop = decodeAs<SystemStop>("00004711 5 00 00 00 00 00 Stopp an alle", &envelope);
    EXPECT_EQ(stop.target, 0x00000000u);
    EXPECT_FALSE(envelope.response);
    EXPECT_EQ(envelope.hash, 0x4711);
    EXPECT_EQ(systemSubcommand(envelope.body), 0x00);
    expectRoundTrip("00004711 5 00 00 00 00 00 Stopp an alle");
}

TEST(Document_2_1_SystemStop, StopToCs2Serial08) {
    // "00004711 5 43 53 32 08 00 Stopp an bestimmten Teilnehmer (CS2 mit SNr. 08)": UID "CS2" + 0x08.
    Message envelope;
    const auto stop = decodeAs<SystemStop>(
        "00004711 5 43 53 32 08 00 Stopp an bestimmten Teilnehmer (CS2 mit SNr. 08)", &envelope);
    EXPECT_EQ(stop.target, 0x43533208u);
    EXPECT_FALSE(envelope.response);
    expectRoundTrip("00004711 5 43 53 32 08 00 Stopp an bestimmten Teilnehmer (CS2 mit SNr. 08)");
}

TEST(Document_2_1_SystemStop, AnswerIsTheCommandWithResponseBit) {
    // "Antwort: Ursprünglicher Befehl mit gesetztem Response Bit".
    Message envelope;
    const auto stop = decodeAs<SystemStop>("00014711 5 43 53 32 08 00", &envelope);
    EXPECT_EQ(stop.target, 0x43533208u);
    EXPECT_TRUE(envelope.response);
    expectRoundTrip("00014711 5 43 53 32 08 00");
}

// ===== 2.2 System Go =============================================================================

TEST(Document_2_2_SystemGo, GoToAll) {
    Message envelope;
    const auto go = decodeAs<SystemGo>("00004711 5 00 00 00 00 01 Go an alle", &envelope);
    EXPECT_EQ(go.target, 0x00000000u);
    EXPECT_FALSE(envelope.response);
    EXPECT_EQ(systemSubcommand(envelope.body), 0x01);
    expectRoundTrip("00004711 5 00 00 00 00 01 Go an alle");
}

TEST(Document_2_2_SystemGo, GoToCs2) {
    // The document's comment says "CS2 mit SNr. 04", but the bytes are the same UID 0x43533208 as in 2.1.
    const auto go =
        decodeAs<SystemGo>("00004711 5 43 53 32 08 01 Go an bestimmten Teilnehmer (CS2 mit SNr. 04)");
    EXPECT_EQ(go.target, 0x43533208u);
    expectRoundTrip("00004711 5 43 53 32 08 01 Go an bestimmten Teilnehmer (CS2 mit SNr. 04)");
}

// ===== 2.3 System Halt ===========================================================================

TEST(Document_2_3_SystemHalt, HaltToAll) {
    Message envelope;
    const auto halt = decodeAs<SystemHalt>("00004711 5 00 00 00 00 02 Halt an alle", &envelope);
    EXPECT_EQ(halt.target, 0x00000000u);
    EXPECT_FALSE(envelope.response);
    EXPECT_EQ(systemSubcommand(envelope.body), 0x02);
    expectRoundTrip("00004711 5 00 00 00 00 02 Halt an alle");
}

TEST(Document_2_3_SystemHalt, HaltToCs2) {
    // As in 2.2 the comment says "SNr. 04" for the bytes of UID 0x43533208.
    const auto halt =
        decodeAs<SystemHalt>("00004711 5 43 53 32 08 02 Halt an bestimmten Teilnehmer (CS2 mit SNr. 04)");
    EXPECT_EQ(halt.target, 0x43533208u);
    expectRoundTrip("00004711 5 43 53 32 08 02 Halt an bestimmten Teilnehmer (CS2 mit SNr. 04)");
}

// ===== 2.4 Loco emergency stop ===================================================================

TEST(Document_2_4_LocoEmergencyStop, Mm2Address72) {
    Message envelope;
    const auto stop =
        decodeAs<LocoEmergencyStop>("00004711 5 00 00 00 48 03   Lok Nothalt MM2 72", &envelope);
    EXPECT_EQ(stop.loco.value(), 0x00000048u);
    EXPECT_EQ(stop.loco.protocol(), Protocol::Mm2);
    EXPECT_EQ(stop.loco.address(), 72u);
    EXPECT_FALSE(envelope.response);
    EXPECT_EQ(systemSubcommand(envelope.body), 0x03);
    expectRoundTrip("00004711 5 00 00 00 48 03   Lok Nothalt MM2 72");
}

TEST(Document_2_4_LocoEmergencyStop, DccAddress3) {
    const auto stop = decodeAs<LocoEmergencyStop>("00004711 5 00 00 C0 03 03   Lok Nothalt DCC  Adr. 3");
    EXPECT_EQ(stop.loco.value(), 0x0000C003u);
    EXPECT_EQ(stop.loco.protocol(), Protocol::Dcc);
    EXPECT_EQ(stop.loco.address(), 3u);
    expectRoundTrip("00004711 5 00 00 C0 03 03   Lok Nothalt DCC  Adr. 3");
}

TEST(Document_2_4_LocoEmergencyStop, MfxSid5) {
    const auto stop = decodeAs<LocoEmergencyStop>("00004711 5 00 00 40 05 03   Lok Nothalt MFX SID 5");
    EXPECT_EQ(stop.loco.value(), 0x00004005u);
    EXPECT_EQ(stop.loco.protocol(), Protocol::Mfx);
    EXPECT_EQ(stop.loco.address(), 5u);
    expectRoundTrip("00004711 5 00 00 40 05 03   Lok Nothalt MFX SID 5");
}

// ===== 2.5 Loco cycle end ========================================================================

TEST(Document_2_5_LocoCycleEnd, Mm2Address72) {
    Message envelope;
    const auto end = decodeAs<LocoCycleEnd>("00004711 5 00 00 00 48 04 Zyklus Ende MM2 72", &envelope);
    EXPECT_EQ(end.loco.value(), 0x00000048u);
    EXPECT_EQ(end.loco.protocol(), Protocol::Mm2);
    EXPECT_EQ(end.loco.address(), 72u);
    EXPECT_EQ(systemSubcommand(envelope.body), 0x04);
    expectRoundTrip("00004711 5 00 00 00 48 04 Zyklus Ende MM2 72");
}

TEST(Document_2_5_LocoCycleEnd, DccAddress3) {
    const auto end = decodeAs<LocoCycleEnd>("00004711 5 00 00 C0 03 04 Zyklus Ende DCC Adr. 3");
    EXPECT_EQ(end.loco.value(), 0x0000C003u);
    EXPECT_EQ(end.loco.protocol(), Protocol::Dcc);
    EXPECT_EQ(end.loco.address(), 3u);
    expectRoundTrip("00004711 5 00 00 C0 03 04 Zyklus Ende DCC Adr. 3");
}

TEST(Document_2_5_LocoCycleEnd, MfxSid5) {
    const auto end = decodeAs<LocoCycleEnd>("00004711 5 00 00 40 05 04 Zyklus Ende MFX SID 5");
    EXPECT_EQ(end.loco.value(), 0x00004005u);
    EXPECT_EQ(end.loco.protocol(), Protocol::Mfx);
    EXPECT_EQ(end.loco.address(), 5u);
    expectRoundTrip("00004711 5 00 00 40 05 04 Zyklus Ende MFX SID 5");
}

TEST(Document_2_5_LocoCycleEnd, AllLocosOfOneStation) {
    // The UID of a track format processor in the Loc-ID field clears that station's whole loco table.
    const auto end = decodeAs<LocoCycleEnd>(
        "00004711 5 43 53 32 08 04 Zyklus Ende alle Loks im Gleis Format Prozessor mit UID=43 53 32 08");
    EXPECT_EQ(end.loco.value(), 0x43533208u);
    EXPECT_EQ(end.loco.range(), LocIdRange::DeviceUid);
    EXPECT_EQ(
        described(
            "00004711 5 43 53 32 08 04 Zyklus Ende alle Loks im Gleis Format Prozessor mit UID=43 53 32 08",
            "locIdRange"),
        "device UID");
    expectRoundTrip(
        "00004711 5 43 53 32 08 04 Zyklus Ende alle Loks im Gleis Format Prozessor mit UID=43 53 32 08");
}

TEST(Document_2_5_LocoCycleEnd, AllLocosOfAllStations) {
    // UID 00 00 00 00 is the broadcast. The Loc-ID type has no broadcast notion: 0 reads as MM2 address 0.
    const auto end = decodeAs<LocoCycleEnd>(
        "00004711 5 00 00 00 00 04 Zyklus Ende alle Loks auf allen Gleis Format Prozessoren");
    EXPECT_EQ(end.loco.value(), 0x00000000u);
    expectRoundTrip("00004711 5 00 00 00 00 04 Zyklus Ende alle Loks auf allen Gleis Format Prozessoren");
}

// ===== 2.6 Loco track sub-protocol ================================================================

TEST(Document_2_6_LocoProtocol, DccAddress3With126Steps) {
    // "00004711 6 00 00 C0 03 05 02 DCC Adr 03 mit 126 Fahrstufen ansteuern": 2 = short address, 126 steps.
    Message envelope;
    const auto protocol = decodeAs<LocoProtocol>(
        "00004711 6 00 00 C0 03 05 02 DCC Adr 03 mit 126 Fahrstufen ansteuern", &envelope);
    EXPECT_EQ(protocol.loco.value(), 0x0000C003u);
    EXPECT_EQ(protocol.loco.protocol(), Protocol::Dcc);
    EXPECT_EQ(protocol.loco.address(), 3u);
    EXPECT_EQ(protocol.trackProtocol, 2);
    EXPECT_EQ(systemSubcommand(envelope.body), 0x05);
    EXPECT_EQ(described("00004711 6 00 00 C0 03 05 02 DCC Adr 03 mit 126 Fahrstufen ansteuern", "value"),
              "dcc-short-126");
    expectRoundTrip("00004711 6 00 00 C0 03 05 02 DCC Adr 03 mit 126 Fahrstufen ansteuern");
}

TEST(Document_2_6_LocoProtocol, SubProtocolTables) {
    // MM2: 0 MM2 2040, 1 MM2_LOK_20, 2 MM2_FKT_40.
    const std::array<std::string_view, 3> mm2{"mm2-2040", "mm2-loco-20khz", "mm2-function-40khz"};
    for (std::uint8_t value = 0; value < mm2.size(); ++value) {
        const std::string text = frameText("00004711", {0x00, 0x00, 0x00, 0x48, 0x05, value});
        EXPECT_EQ(decodeAs<LocoProtocol>(text).trackProtocol, value);
        EXPECT_EQ(described(text, "value"), mm2[value]);
        expectRoundTrip(text);
    }
    // DCC: 0 short/28 (default), 1 short/14, 2 short/126, 3 long/28, 4 long/126.
    const std::array<std::string_view, 5> dcc{"dcc-short-28", "dcc-short-14", "dcc-short-126", "dcc-long-28",
                                              "dcc-long-126"};
    for (std::uint8_t value = 0; value < dcc.size(); ++value) {
        const std::string text = frameText("00004711", {0x00, 0x00, 0xC0, 0x03, 0x05, value});
        EXPECT_EQ(decodeAs<LocoProtocol>(text).trackProtocol, value);
        EXPECT_EQ(described(text, "value"), dcc[value]);
        expectRoundTrip(text);
    }
    // Values outside the lists do not exist for the loco's protocol.
    expectRefused("00004711 6 00 00 00 48 05 03", DecodeErrorKind::ReservedValue);
    expectRefused("00004711 6 00 00 C0 03 05 05", DecodeErrorKind::ReservedValue);
    expectRefused("00004711 5 00 00 C0 03 05", DecodeErrorKind::UnexpectedLength);
}

// ===== 2.7 Accessory switch time ==================================================================

TEST(Document_2_7_AccessorySwitchTime, Time100ms) {
    // The document prints "00004711 7 00 00 00 00 06 0A" (6 bytes for DLC 7); intended: 16-bit time 00 0A =
    // 100 ms.
    Message envelope;
    const auto time = decodeAs<AccessorySwitchTime>("00004711 7 00 00 00 00 06 00 0A", &envelope);
    EXPECT_EQ(time.target, 0x00000000u);
    EXPECT_EQ(time.time10ms, 10);
    EXPECT_EQ(systemSubcommand(envelope.body), 0x06);
    EXPECT_EQ(described("00004711 7 00 00 00 00 06 00 0A", "switchTimeMs"), "100");
    expectRoundTrip("00004711 7 00 00 00 00 06 00 0A");
}

TEST(Document_2_7_AccessorySwitchTime, LiteralExampleIsRefused) {
    const auto bytesOnly = can::parseFrame("00004711 7 00 00 00 00 06 0A");
    ASSERT_FALSE(bytesOnly.hasValue());
    EXPECT_TRUE(contains(bytesOnly.error(), "DLC 7 announces 7 data bytes, only 6 given"))
        << bytesOnly.error();
    // As printed, with its comment: the comment's first word stands where the seventh byte should be.
    const auto asPrinted = can::parseFrame("00004711 7 00 00 00 00 06 0A Schaltzeit 100 ms festlegen");
    ASSERT_FALSE(asPrinted.hasValue());
    EXPECT_TRUE(contains(asPrinted.error(), "'Schaltzeit'")) << asPrinted.error();
}

TEST(Document_2_7_AccessorySwitchTime, ZeroRestoresTheDefault) {
    // "Wert 0 ist wieder Defaultschaltzeit"; the overview table of 1.4 lists DLC 5, which carries no time.
    EXPECT_EQ(decodeAs<AccessorySwitchTime>("00004711 7 00 00 00 00 06 00 00").time10ms, 0);
    EXPECT_FALSE(decodeAs<AccessorySwitchTime>("00004711 5 00 00 00 00 06").time10ms.has_value());
    // At most 163 s ("rund 2:45 min"): 16300 x 10 ms fits the 16-bit field.
    EXPECT_EQ(decodeAs<AccessorySwitchTime>("00004711 7 00 00 00 00 06 3F AC").time10ms, 16300);
    expectRoundTrip("00004711 7 00 00 00 00 06 00 00");
    expectRoundTrip("00004711 5 00 00 00 00 06");
    expectRoundTrip("00004711 7 00 00 00 00 06 3F AC");
}

// ===== 2.8 mfx fast read (no example in the document; frame built from the format table) ===========

TEST(Document_2_8_MfxFastRead, Cs2FastReadForSid5) {
    // DLC 7: sender UID, sub-command 0x07, MFX-SID (16 bit). The 1.4 overview says DLC 6, the format 7.
    Message envelope;
    const auto fast = decodeAs<MfxFastRead>("00004711 7 43 53 32 08 07 00 05", &envelope);
    EXPECT_EQ(fast.sender, 0x43533208u);
    EXPECT_EQ(fast.sid, 5);
    EXPECT_EQ(systemSubcommand(envelope.body), 0x07);
    expectRoundTrip("00004711 7 43 53 32 08 07 00 05");
    expectRoundTrip(
        "00014711 7 43 53 32 08 07 00 05"); // "Immer: Ursprünglicher Befehl mit gesetztem Response Bit"
}

// ===== 2.9 Track protocols (value table) =========================================================

TEST(Document_2_9_TrackProtocols, BitTable) {
    // Bit 0 MM2, bit 1 MFX, bit 2 DCC; a set bit enables the protocol; bits 3..7 are reserved.
    struct Row {
        std::uint8_t mask;
        std::string_view protocols;
    };
    const Row rows[] = {{0x00, "none"},    {0x01, "mm2"},     {0x02, "mfx"},     {0x04, "dcc"},
                        {0x03, "mm2,mfx"}, {0x05, "mm2,dcc"}, {0x06, "mfx,dcc"}, {0x07, "mm2,mfx,dcc"}};
    for (const auto& row : rows) {
        const std::string text = frameText("00004711", {0x43, 0x53, 0x32, 0x08, 0x08, row.mask});
        SCOPED_TRACE(text);
        const auto protocols = decodeAs<TrackProtocols>(text);
        EXPECT_EQ(protocols.target, 0x43533208u);
        EXPECT_EQ(protocols.mask, row.mask);
        EXPECT_EQ(described(text, "protocols"), row.protocols);
        expectRoundTrip(text);
    }
    for (std::uint8_t reserved = 0x08; reserved != 0; reserved = std::uint8_t(reserved << 1))
        expectRefused(frameText("00004711", {0x43, 0x53, 0x32, 0x08, 0x08, std::uint8_t(reserved | 0x07)}),
                      DecodeErrorKind::ReservedValue);
}

// ===== 2.10 mfx registration counter =============================================================

TEST(Document_2_10_MfxRegistrationCounter, Cs2CounterTo2) {
    // "00004711 7 43 53 32 08 09 00 02 Setzen Neuanmeldezähler auf 2."
    Message envelope;
    const auto counter = decodeAs<MfxRegistrationCounter>(
        "00004711 7 43 53 32 08 09 00 02 Setzen Neuanmeldezähler auf 2.", &envelope);
    EXPECT_EQ(counter.target, 0x43533208u);
    EXPECT_EQ(counter.counter, 2);
    EXPECT_EQ(systemSubcommand(envelope.body), 0x09);
    expectRoundTrip("00004711 7 43 53 32 08 09 00 02 Setzen Neuanmeldezähler auf 2.");
}

// ===== 2.11 Overload ==============================================================================

TEST(Document_2_11_Overload, Channel1AsPrinted) {
    // "00004711 6 43 53 32 08 0A 01 Kanalnummer 1 meldet Überlast." The example has no response bit although
    // the command is "nur als Antwort gesendet"; the decoder accepts it either way.
    Message envelope;
    const auto overload =
        decodeAs<Overload>("00004711 6 43 53 32 08 0A 01 Kanalnummer 1 meldet Überlast.", &envelope);
    EXPECT_EQ(overload.sender, 0x43533208u);
    EXPECT_EQ(overload.channel, 1);
    EXPECT_FALSE(envelope.response);
    EXPECT_EQ(systemSubcommand(envelope.body), 0x0A);
    expectRoundTrip("00004711 6 43 53 32 08 0A 01 Kanalnummer 1 meldet Überlast.");
}

TEST(Document_2_11_Overload, Channel1AsResponse) {
    // The form a station actually sends: the same bytes with the response bit.
    Message envelope;
    const auto overload = decodeAs<Overload>("00014711 6 43 53 32 08 0A 01", &envelope);
    EXPECT_EQ(overload.sender, 0x43533208u);
    EXPECT_EQ(overload.channel, 1);
    EXPECT_TRUE(envelope.response);
    expectRoundTrip("00014711 6 43 53 32 08 0A 01");
}

// ===== 2.12 System status =========================================================================

TEST(Document_2_12_SystemStatus, QueryChannel1) {
    // "00004711 6 43 53 32 08 0B 01 Abfrage des Messwertes Kanalnummer 1"
    Message envelope;
    const auto status = decodeAs<SystemStatus>(
        "00004711 6 43 53 32 08 0B 01 Abfrage des Messwertes Kanalnummer 1", &envelope);
    EXPECT_EQ(status.device, 0x43533208u);
    EXPECT_EQ(status.channel, 1);
    EXPECT_FALSE(status.value.has_value());
    EXPECT_FALSE(status.accepted.has_value());
    EXPECT_FALSE(envelope.response);
    EXPECT_EQ(systemSubcommand(envelope.body), 0x0B);
    expectRoundTrip("00004711 6 43 53 32 08 0B 01 Abfrage des Messwertes Kanalnummer 1");
}

TEST(Document_2_12_SystemStatus, AnswerWithReading3) {
    // "00014711 8 43 53 32 08 0B 01 00 03 Antwort mit Messwert": response bit set, reading 0x0003.
    Message envelope;
    const auto status =
        decodeAs<SystemStatus>("00014711 8 43 53 32 08 0B 01 00 03 Antwort mit Messwert", &envelope);
    EXPECT_EQ(status.device, 0x43533208u);
    EXPECT_EQ(status.channel, 1);
    EXPECT_EQ(status.value, 3);
    EXPECT_FALSE(status.accepted.has_value());
    EXPECT_TRUE(envelope.response);
    expectRoundTrip("00014711 8 43 53 32 08 0B 01 00 03 Antwort mit Messwert");
}

TEST(Document_2_12_SystemStatus, FormTable) {
    // DLC 8 without response bit: set configuration value (here channel 5 to 500, the slider of 6.2).
    Message envelope;
    const auto set = decodeAs<SystemStatus>("00004711 8 43 53 32 08 0B 05 01 F4", &envelope);
    EXPECT_FALSE(envelope.response);
    EXPECT_EQ(set.channel, 5);
    EXPECT_EQ(set.value, 500);
    expectRoundTrip("00004711 8 43 53 32 08 0B 05 01 F4");
    // DLC 7 answer: TRUE (0x01) valid, FALSE (0x00) invalid; other values are no answer.
    EXPECT_EQ(decodeAs<SystemStatus>("00014711 7 43 53 32 08 0B 05 01").accepted, true);
    EXPECT_EQ(decodeAs<SystemStatus>("00014711 7 43 53 32 08 0B 05 00").accepted, false);
    EXPECT_EQ(described("00014711 7 43 53 32 08 0B 05 01", "accepted"), "true");
    expectRoundTrip("00014711 7 43 53 32 08 0B 05 01");
    expectRoundTrip("00014711 7 43 53 32 08 0B 05 00");
    expectRefused("00014711 7 43 53 32 08 0B 05 02", DecodeErrorKind::ReservedValue);
    // Unknown channel: the request is confirmed with DLC 6 and no reading.
    const auto unknown = decodeAs<SystemStatus>("00014711 6 43 53 32 08 0B 07", &envelope);
    EXPECT_TRUE(envelope.response);
    EXPECT_FALSE(unknown.value.has_value());
    expectRoundTrip("00014711 6 43 53 32 08 0B 07");
    // A query to the broadcast address is possible.
    EXPECT_EQ(decodeAs<SystemStatus>("00004711 6 00 00 00 00 0B 01").device, 0x00000000u);
}

// ===== 2.13 Device id (no example in the document; frames built from the format table) ==========

TEST(Document_2_13_DeviceId, QueryWithoutId) {
    Message envelope;
    const auto query = decodeAs<DeviceId>("00004711 5 43 53 32 08 0C", &envelope);
    EXPECT_EQ(query.target, 0x43533208u);
    EXPECT_FALSE(query.deviceId.has_value());
    EXPECT_EQ(systemSubcommand(envelope.body), 0x0C);
    expectRoundTrip("00004711 5 43 53 32 08 0C");
}

TEST(Document_2_13_DeviceId, SetAndAnswer) {
    Message envelope;
    const auto set = decodeAs<DeviceId>("00004711 7 43 53 32 08 0C 00 05", &envelope);
    EXPECT_EQ(set.target, 0x43533208u);
    EXPECT_EQ(set.deviceId, 0x0005);
    EXPECT_FALSE(envelope.response);
    const auto answer = decodeAs<DeviceId>("00014711 7 43 53 32 08 0C 00 05", &envelope);
    EXPECT_EQ(answer.deviceId, 0x0005);
    EXPECT_TRUE(envelope.response);
    expectRoundTrip("00004711 7 43 53 32 08 0C 00 05");
    expectRoundTrip("00014711 7 43 53 32 08 0C 00 05");
    expectRefused("00004711 6 43 53 32 08 0C 00", DecodeErrorKind::UnexpectedLength);
}

// ===== 2.14 System reset (no example in the document; frame built from the format table) =========

TEST(Document_2_14_SystemReset, ResetCs2) {
    Message envelope;
    const auto reset = decodeAs<SystemReset>("00004711 6 43 53 32 08 80 FF", &envelope);
    EXPECT_EQ(reset.target, 0x43533208u);
    EXPECT_EQ(reset.resetTarget, 0xFF);
    EXPECT_EQ(systemSubcommand(envelope.body), 0x80);
    expectRoundTrip("00004711 6 43 53 32 08 80 FF");
}

} // namespace
} // namespace stellwerk::cs2
