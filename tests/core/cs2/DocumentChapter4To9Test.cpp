// The examples of Märklin's CS2 CAN protocol document (shared/seeds/003_e81750172fa08e9b.txt) in chapters 4-7
// and 9 (accessories, feedback, devices and status data, config data, automation), decoded through the typed
// API, checked against the meaning the document gives them, and encoded back to the same bytes. Sections that
// print no example frame get frames built from the section's format table (the test says so).
//
// Example lines are quoted as the document prints them, comment included (parseFrame takes text after
// the data bytes as a comment). All frames use the document's hash 0x4711 unless a test says otherwise.

#include "DocumentExamplesSupport.h"
#include "can/FrameText.h"
#include "cs2/Automation.h"
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

using test::configRequest;
using test::decodeAs;
using test::described;
using test::expectRefused;
using test::expectRoundTrip;
using test::frameText;

// ===== 4.1 Accessory switch (no example frame in the document; frames built from the format table) =

TEST(Document_4_1_AccessorySwitch, Mm2AccessoryOnWithDefaultTime) {
    // DLC 6: position and current, switched off after the default time.
    Message envelope;
    const auto command = decodeAs<AccessorySwitch>("00164711 6 00 00 30 03 01 01", &envelope);
    EXPECT_EQ(command.article.value(), 0x00003003u);
    EXPECT_EQ(command.article.protocol(), Protocol::Mm2Accessory);
    EXPECT_EQ(command.position, 1);
    EXPECT_EQ(command.current, 1);
    EXPECT_FALSE(command.time10ms.has_value());
    EXPECT_FALSE(envelope.response);
    expectRoundTrip("00164711 6 00 00 30 03 01 01");
    expectRoundTrip("00174711 6 00 00 30 03 01 01"); // the answer
}

TEST(Document_4_1_AccessorySwitch, SwitchOffWithCurrent0) {
    const auto command = decodeAs<AccessorySwitch>("00164711 6 00 00 30 03 01 00");
    EXPECT_EQ(command.current, 0);
    expectRoundTrip("00164711 6 00 00 30 03 01 00");
}

TEST(Document_4_1_AccessorySwitch, DccAccessoryWithSwitchTime) {
    // DLC 8: switch time in 10 ms steps; 0 = only switch on.
    const auto timed = decodeAs<AccessorySwitch>("00164711 8 00 00 38 00 00 01 00 0A");
    EXPECT_EQ(timed.article.value(), 0x00003800u);
    EXPECT_EQ(timed.article.protocol(), Protocol::DccAccessory);
    EXPECT_EQ(timed.position, 0);
    EXPECT_EQ(timed.current, 1);
    EXPECT_EQ(timed.time10ms, 10);
    EXPECT_EQ(described("00164711 8 00 00 38 00 00 01 00 0A", "switchTimeMs"), "100");
    EXPECT_EQ(decodeAs<AccessorySwitch>("00164711 8 00 00 38 00 01 01 00 00").time10ms, 0);
    expectRoundTrip("00164711 8 00 00 38 00 00 01 00 0A");
    expectRoundTrip("00164711 8 00 00 38 00 01 01 00 00");
}

TEST(Document_4_1_AccessorySwitch, PositionAndCurrentRanges) {
    // Position 0..255 (MM3 bits 0,1: 11 = white / SH0), current 0..31.
    const auto white = decodeAs<AccessorySwitch>("00164711 6 00 00 30 00 03 1F");
    EXPECT_EQ(white.position, 3);
    EXPECT_EQ(white.current, 31);
    expectRoundTrip("00164711 6 00 00 30 00 03 1F");
    expectRefused("00164711 6 00 00 30 00 03 20", DecodeErrorKind::ReservedValue);
    expectRefused("00164711 7 00 00 30 00 03 01 00", DecodeErrorKind::UnexpectedLength);
}

// ===== 5.1 S88 polling (no example in the document; frames built from the format table) ==========

TEST(Document_5_1_S88Poll, RequestTwoModules) {
    const auto poll = decodeAs<S88Poll>("00204711 5 43 53 32 08 02");
    EXPECT_EQ(poll.device, 0x43533208u);
    EXPECT_EQ(poll.moduleCount, 2);
    EXPECT_FALSE(poll.module.has_value());
    expectRoundTrip("00204711 5 43 53 32 08 02");
}

TEST(Document_5_1_S88Poll, AnswerPerModule) {
    // One answer per module with the 16 inputs' state.
    Message envelope;
    const auto answer = decodeAs<S88Poll>("00214711 7 43 53 32 08 01 80 01", &envelope);
    EXPECT_TRUE(envelope.response);
    EXPECT_EQ(answer.device, 0x43533208u);
    EXPECT_EQ(answer.module, 1);
    EXPECT_EQ(answer.state, 0x8001);
    EXPECT_FALSE(answer.moduleCount.has_value());
    expectRoundTrip("00214711 7 43 53 32 08 01 80 01");
}

// ===== 5.2 Feedback event (no example in the document; frames built from the format table) =======

TEST(Document_5_2_S88Event, QueryContact) {
    // Form 1, DLC 4: device id (16 bit) and contact id (16 bit).
    const auto query = decodeAs<S88Event>("00224711 4 00 01 00 0B");
    EXPECT_EQ(query.device, 0x0001);
    EXPECT_EQ(query.contact, 11);
    EXPECT_FALSE(query.parameter.has_value());
    EXPECT_FALSE(query.change.has_value());
    expectRoundTrip("00224711 4 00 01 00 0B");
}

TEST(Document_5_2_S88Event, RegisterContact) {
    // Form 2, DLC 5: register the input and switch on change messages, with a parameter.
    const auto registration = decodeAs<S88Event>("00224711 5 00 01 00 0B 01");
    EXPECT_EQ(registration.contact, 11);
    EXPECT_EQ(registration.parameter, 1);
    expectRoundTrip("00224711 5 00 01 00 0B 01");
}

TEST(Document_5_2_S88Event, AnswerWithOldAndNewState) {
    // The answer is always DLC 8: old state, new state, time.
    Message envelope;
    const auto event = decodeAs<S88Event>("00234711 8 00 01 00 0B 00 01 00 32", &envelope);
    EXPECT_TRUE(envelope.response);
    EXPECT_EQ(event.device, 0x0001);
    EXPECT_EQ(event.contact, 11);
    ASSERT_TRUE(event.change.has_value());
    EXPECT_EQ(event.change->oldState, 0);
    EXPECT_EQ(event.change->newState, 1);
    EXPECT_EQ(event.change->time10ms, 50);
    expectRoundTrip("00234711 8 00 01 00 0B 00 01 00 32");
    expectRefused("00224711 6 00 01 00 0B 00 01", DecodeErrorKind::UnexpectedLength);
}

// ===== 6.1 Ping =====================================================================================

TEST(Document_6_1_Ping, QueryAllDevices) {
    Message envelope;
    const auto ping = decodeAs<Ping>("00304711 0", &envelope);
    EXPECT_FALSE(ping.identity.has_value());
    EXPECT_FALSE(envelope.response);
    expectRoundTrip("00304711 0");
}

TEST(Document_6_1_Ping, AnswerWithDeviceTypeTable) {
    // DLC 8: sender UID, software version, device type (big endian, bytes 6-7). Versions illustrative.
    struct Row {
        std::uint16_t type;
        std::string_view name;
    };
    const Row rows[] = {
        {0x0000, "Track format processor 60213/60214 or booster 60173/60174"},
        {0x0010, "Gleisbox 60112/60113"},
        {0x0020, "Connect 6021 (60128)"},
        {0x0030, "Mobile Station 2"},
        {0xFFE0, "Wireless device"},
        {0xFFFF, "Central Station GUI (master)"},
    };
    for (const auto& row : rows) {
        const std::string text = frameText("00314711", {0x43, 0x53, 0x32, 0x08, 0x01, 0x27,
                                                        std::uint8_t(row.type >> 8), std::uint8_t(row.type)});
        SCOPED_TRACE(text);
        Message envelope;
        const auto ping = decodeAs<Ping>(text, &envelope);
        EXPECT_TRUE(envelope.response);
        ASSERT_TRUE(ping.identity.has_value());
        EXPECT_EQ(ping.identity->uid, 0x43533208u);
        EXPECT_EQ(ping.identity->versionMajor, 1);
        EXPECT_EQ(ping.identity->versionMinor, 0x27);
        EXPECT_EQ(ping.identity->deviceType, row.type);
        EXPECT_EQ(deviceTypeName(row.type), row.name);
        EXPECT_EQ(described(text, "deviceName"), row.name);
        EXPECT_EQ(described(text, "version"), "1.39");
        expectRoundTrip(text);
    }
    expectRefused("00314711 4 43 53 32 08", DecodeErrorKind::UnexpectedLength);
}

// ===== 6.2 Status data configuration (no example frame; frames built from the format table) ======

TEST(Document_6_2_StatusDataConfig, RequestDeviceDescription) {
    // DLC 5: target UID and index; index 0 is the device description.
    Message envelope;
    const auto request = decodeAs<StatusDataConfig>("003A4711 5 43 53 32 08 00", &envelope);
    EXPECT_FALSE(envelope.response);
    EXPECT_EQ(request.form, StatusDataConfig::Form::Request);
    EXPECT_EQ(request.device, 0x43533208u);
    EXPECT_EQ(request.index, 0);
    expectRoundTrip("003A4711 5 43 53 32 08 00");
}

TEST(Document_6_2_StatusDataConfig, DataPacketCarriesPacketNumberInHash) {
    // "im Hash befindet sich die Paketnummer": packet 1 = hash 0x0301. Index 1 data: channel 1, power -3.
    Message envelope;
    const auto packet = decodeAs<StatusDataConfig>("003B0301 8 01 FD 30 F0 E0 C0 00 0F", &envelope);
    EXPECT_TRUE(envelope.response);
    EXPECT_EQ(packetNumberFromHash(envelope.hash), 1);
    EXPECT_EQ(packet.form, StatusDataConfig::Form::Packet);
    EXPECT_EQ(packet.packet.size, 8);
    EXPECT_EQ(packet.packet.bytes[0], 0x01);
    EXPECT_EQ(std::int8_t(packet.packet.bytes[1]), -3);
    EXPECT_EQ(described("003B0301 8 01 FD 30 F0 E0 C0 00 0F", "packet"), "1");
    expectRoundTrip("003B0301 8 01 FD 30 F0 E0 C0 00 0F");
}

TEST(Document_6_2_StatusDataConfig, EndFrameWithPacketCount) {
    // DLC 6 with response bit: the original request plus the number of packets sent.
    const auto end = decodeAs<StatusDataConfig>("003B4711 6 43 53 32 08 01 05");
    EXPECT_EQ(end.form, StatusDataConfig::Form::End);
    EXPECT_EQ(end.device, 0x43533208u);
    EXPECT_EQ(end.index, 1);
    EXPECT_EQ(end.packetCount, 5);
    expectRoundTrip("003B4711 6 43 53 32 08 01 05");
}

// ===== 7.1 Config data request =======================================================================

TEST(Document_7_1_ConfigDataRequest, RequestLoks) {
    // "loks": the complete loco list, zlib compressed.
    Message envelope;
    const auto request = decodeAs<ConfigDataRequest>("00404711 8 6C 6F 6B 73 00 00 00 00", &envelope);
    EXPECT_EQ(request.text(), "loks");
    EXPECT_FALSE(envelope.response);
    EXPECT_EQ(described("00404711 8 6C 6F 6B 73 00 00 00 00", "filename"), "loks");
    expectRoundTrip("00404711 8 6C 6F 6B 73 00 00 00 00");
}

TEST(Document_7_1_ConfigDataRequest, AcknowledgedWithResponseBit) {
    Message envelope;
    const auto ack = decodeAs<ConfigDataRequest>("00414711 8 6C 6F 6B 73 00 00 00 00", &envelope);
    EXPECT_EQ(ack.text(), "loks");
    EXPECT_TRUE(envelope.response);
    expectRoundTrip("00414711 8 6C 6F 6B 73 00 00 00 00");
}

TEST(Document_7_1_ConfigDataRequest, FileNameTable) {
    // Every name of the table; "gbs-#" with page 1. Eight-character names fill the frame without a NUL.
    for (std::string_view key :
         {"lokinfo", "loknamen", "maginfo", "lokdb", "lang", "ldbver", "langver", "loks", "mags", "gbs",
          "gbs-1", "fs", "loksstat", "magstat", "gbsstat", "fsstat"}) {
        const std::string text = configRequest("00404711", key);
        SCOPED_TRACE(text);
        EXPECT_EQ(decodeAs<ConfigDataRequest>(text).text(), key);
        expectRoundTrip(text);
    }
    expectRefused("00404711 4 6C 6F 6B 73", DecodeErrorKind::UnexpectedLength);
}

// ===== 7.2 Config data stream =======================================================================

TEST(Document_7_2_ConfigDataStream, HeaderDlc6) {
    // First packet of an answer to a request: file length and CRC.
    const auto header = decodeAs<ConfigDataStream>("00424711 6 00 00 00 5F 21 70");
    EXPECT_EQ(header.form, ConfigDataStream::Form::Header);
    EXPECT_EQ(header.length, 0x5Fu);
    EXPECT_EQ(header.crc, 0x2170);
    expectRoundTrip("00424711 6 00 00 00 5F 21 70");
}

TEST(Document_7_2_ConfigDataStream, BroadcastHeaderDlc7) {
    // First packet of a broadcast of a configuration change: length, CRC and a reserved byte.
    const auto header = decodeAs<ConfigDataStream>("00424711 7 00 00 00 5F 21 70 7B");
    EXPECT_EQ(header.form, ConfigDataStream::Form::BroadcastHeader);
    EXPECT_EQ(header.length, 0x5Fu);
    EXPECT_EQ(header.crc, 0x2170);
    EXPECT_EQ(header.extra, 0x7B);
    expectRoundTrip("00424711 7 00 00 00 5F 21 70 7B");
}

TEST(Document_7_2_ConfigDataStream, DataPacketDlc8) {
    const auto data = decodeAs<ConfigDataStream>("00424711 8 00 00 00 AA 78 9C 8B 4E");
    EXPECT_EQ(data.form, ConfigDataStream::Form::Data);
    const std::array<std::uint8_t, 8> bytes{0x00, 0x00, 0x00, 0xAA, 0x78, 0x9C, 0x8B, 0x4E};
    EXPECT_EQ(data.data, bytes);
    expectRoundTrip("00424711 8 00 00 00 AA 78 9C 8B 4E");
}

TEST(Document_7_2_ConfigDataStream, OtherLengthsEndTheStream) {
    // "Tritt im Datenstrom eine andere Länge auf, so ist der Empfang abzubrechen."
    for (const char* text : {"00424711 0", "00424711 4 00 00 00 5F", "00424711 5 00 00 00 5F 21"})
        expectRefused(text, DecodeErrorKind::UnexpectedLength);
}

// The document's updateCRC, transcribed.
std::uint16_t documentUpdateCrc(std::uint16_t acc, std::uint8_t input) {
    acc = std::uint16_t(acc ^ (input << 8));
    for (int i = 0; i < 8; i++)
        acc = (acc & 0x8000) == 0x8000 ? std::uint16_t((acc << 1) ^ 0x1021) : std::uint16_t(acc << 1);
    return acc;
}

TEST(Document_7_2_ConfigDataStream, CrcAlgorithm) {
    // Start value 0xFFFF, polynomial 0x1021, as the document's updateCRC computes it.
    std::vector<std::uint8_t> bytes;
    for (unsigned i = 0; i < 300; ++i)
        bytes.push_back(std::uint8_t(i * 37 + 11));
    std::uint16_t expected = 0xFFFF;
    for (std::size_t n = 0; n < bytes.size(); ++n) {
        ASSERT_EQ(crc16(std::span(bytes.data(), n)), expected) << n;
        expected = documentUpdateCrc(expected, bytes[n]);
    }
}

// ===== 9.1 Automation ===============================================================================

TEST(Document_9_1_AutomationSwitch, ActivateA1) {
    // DLC 6: device id, automation function ("A1" = 0x4131), position (1 = activate), parameter.
    Message envelope;
    const auto command = decodeAs<AutomationSwitch>("00604711 6 00 05 41 31 01 00", &envelope);
    EXPECT_FALSE(envelope.response);
    EXPECT_EQ(command.device, 0x0005);
    EXPECT_EQ(command.function, 0x4131);
    EXPECT_EQ(command.position, 1);
    EXPECT_EQ(command.parameter, 0);
    EXPECT_FALSE(command.loco.has_value());
    EXPECT_EQ(described("00604711 6 00 05 41 31 01 00", "memory"), "A1");
    EXPECT_EQ(described("00604711 6 00 05 41 31 01 00", "position"), "1");
    expectRoundTrip("00604711 6 00 05 41 31 01 00");
}

TEST(Document_9_1_AutomationSwitch, ReleaseA1) {
    // Position 0 = release / deactivate.
    const auto command = decodeAs<AutomationSwitch>("00604711 6 00 05 41 31 00 00");
    EXPECT_EQ(command.function, 0x4131);
    EXPECT_EQ(command.position, 0);
    expectRoundTrip("00604711 6 00 05 41 31 00 00");
}

TEST(Document_9_1_AutomationSwitch, StatusValueTable) {
    struct Row {
        std::uint8_t status;
        std::string_view name;
    };
    const Row rows[] = {{0, "deactivated"}, {1, "activated"},      {2, "running"},
                        {3, "block-free"},  {4, "block-occupied"}, {5, "suspended"},
                        {6, "reserved"},    {254, "waiting"},      {255, "error"}};
    for (const auto& row : rows) {
        const std::string text = frameText("00614711", {0x00, 0x05, 0x41, 0x31, row.status, 0x00});
        SCOPED_TRACE(text);
        Message envelope;
        const auto status = decodeAs<AutomationSwitch>(text, &envelope);
        EXPECT_TRUE(envelope.response);
        EXPECT_EQ(status.position, row.status);
        EXPECT_EQ(described(text, "status"), row.name);
        expectRoundTrip(text);
    }
    // Unknown states are kept as received (the document asks displays to show them as "Status unbekannt").
    EXPECT_EQ(decodeAs<AutomationSwitch>("00614711 6 00 05 41 31 07 00").position, 7);
    EXPECT_EQ(described("00614711 6 00 05 41 31 07 00", "status"), "7");
    expectRoundTrip("00614711 6 00 05 41 31 07 00");
}

TEST(Document_9_1_AutomationSwitch, BlockWithLoco) {
    // DLC 8 answer: device id, function, the Loc-ID of the loco in the block (here mfx SID 5).
    Message envelope;
    const auto block = decodeAs<AutomationSwitch>("00614711 8 00 05 41 32 00 00 40 05", &envelope);
    EXPECT_TRUE(envelope.response);
    EXPECT_EQ(block.device, 0x0005);
    EXPECT_EQ(block.function, 0x4132);
    ASSERT_TRUE(block.loco.has_value());
    EXPECT_EQ(block.loco->value(), 0x00004005u);
    EXPECT_EQ(block.loco->protocol(), Protocol::Mfx);
    EXPECT_EQ(block.loco->address(), 5u);
    expectRoundTrip("00614711 8 00 05 41 32 00 00 40 05");
    expectRefused("00604711 7 00 05 41 32 00 00 40", DecodeErrorKind::UnexpectedLength);
}

TEST(Document_9_1_AutomationSwitch, BroadcastDevice) {
    // "Sonderfall Broadcastadresse: Die Funktion wird NUR vom Master ausgeführt."
    EXPECT_EQ(decodeAs<AutomationSwitch>("00604711 6 00 00 41 31 01 00").device, 0x0000);
    expectRoundTrip("00604711 6 00 00 41 31 01 00");
}

TEST(Document_9_1_AutomationSwitch, UnknownStatusIsShownAsUnknown) {
    // "ein Endgerät [muss] unbekannte Stati ... als 'Automatikfunktion Ablauffehler' mit Darstellung 'Status
    // unbekannt' interpretieren": the value is kept, and the description says it is unknown.
    EXPECT_EQ(described("00614711 6 00 05 41 31 07 00", "state"), "unknown");
    EXPECT_EQ(described("00614711 6 00 05 41 31 FD 00", "state"), "unknown");
    EXPECT_EQ(described("00614711 6 00 05 41 31 04 00", "state"), "<none>");
    EXPECT_EQ(described("00614711 6 00 05 41 31 FF 00", "state"), "<none>"); // error is a known state
    EXPECT_FALSE(automationStateOf(7).has_value());
    EXPECT_FALSE(automationStateOf(253).has_value());
}

TEST(Document_9_1_AutomationSwitch, StatusValuesAreTheDocumentsStates) {
    EXPECT_EQ(automationStateOf(0), AutomationState::Deactivated);
    EXPECT_EQ(automationStateOf(1), AutomationState::Activated);
    EXPECT_EQ(automationStateOf(2), AutomationState::Running);
    EXPECT_EQ(automationStateOf(3), AutomationState::BlockFree);
    EXPECT_EQ(automationStateOf(4), AutomationState::BlockOccupied);
    EXPECT_EQ(automationStateOf(5), AutomationState::Suspended);
    EXPECT_EQ(automationStateOf(6), AutomationState::Reserved);
    EXPECT_EQ(automationStateOf(254), AutomationState::Waiting);
    EXPECT_EQ(automationStateOf(255), AutomationState::Error);
    EXPECT_EQ(automationStateName(AutomationState::BlockOccupied), "block-occupied");
}

TEST(Document_9_1_AutomationSwitch, RequestEncodesAsTheFormatTable) {
    // Built from the typed message: DLC 6, device high/low, function high/low, position, parameter.
    const Message request{
        0, false, 0x4711,
        AutomationSwitch{0x0005, MemoryFunction::fromText("B3")->wire(), 1, 0, std::nullopt}};
    EXPECT_EQ(formatDocument(encode(request)), "00604711 6 00 05 42 33 01 00");
    const Message status{0, true, 0x4711, AutomationSwitch{0x0005, 0x4233, 4, 0, std::nullopt}};
    EXPECT_EQ(formatDocument(encode(status)), "00614711 6 00 05 42 33 04 00");
}

TEST(Document_1_3_2_2_MemoryFunctions, RowsAToZThenAToZColumnsOneToEight) {
    // "Im Highbyte der Zeilen-Index (Wertebereich: A-Z, a-z) und im Lowbyte der Spaltenindex (1-8)".
    EXPECT_EQ(MemoryFunction::fromWire(0x4131)->text(), "A1");
    EXPECT_EQ(MemoryFunction::fromWire(0x4131)->number(), 1);
    EXPECT_EQ(MemoryFunction::fromWire(0x4138)->number(), 8);
    EXPECT_EQ(MemoryFunction::fromWire(0x4231)->number(), 9);
    EXPECT_EQ(MemoryFunction::fromWire(0x5A38)->number(), 208); // Z8
    EXPECT_EQ(MemoryFunction::fromWire(0x6131)->number(), 209); // a1
    EXPECT_EQ(MemoryFunction::fromWire(0x7A38)->number(), 416); // z8
    EXPECT_EQ(MemoryFunction::fromNumber(209)->text(), "a1");
    EXPECT_EQ(MemoryFunction::fromNumber(416)->wire(), 0x7A38);
    EXPECT_EQ(MemoryFunction::fromText("c5")->row(), 'c');
    EXPECT_EQ(MemoryFunction::fromText("c5")->column(), 5);
    for (int n = 1; n <= MemoryFunction::Count; ++n)
        ASSERT_EQ(MemoryFunction::fromWire(MemoryFunction::fromNumber(n)->wire())->number(), n);
    // Outside A1..z8: the reserved gap ("A0"), a ninth column, S88 contacts, and numbers beyond the memory.
    EXPECT_FALSE(MemoryFunction::fromWire(0x4130).has_value());
    EXPECT_FALSE(MemoryFunction::fromWire(0x4139).has_value());
    EXPECT_FALSE(MemoryFunction::fromWire(0x5B31).has_value());
    EXPECT_FALSE(MemoryFunction::fromWire(0x0005).has_value());
    EXPECT_FALSE(MemoryFunction::fromNumber(0).has_value());
    EXPECT_FALSE(MemoryFunction::fromNumber(417).has_value());
    EXPECT_FALSE(MemoryFunction::fromText("A").has_value());
    EXPECT_EQ(described("00604711 6 00 05 41 39 01 00", "memory"), "<none>");
}

} // namespace
} // namespace stellwerk::cs2
