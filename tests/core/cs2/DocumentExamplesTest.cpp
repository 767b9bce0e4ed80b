// Every example of Märklin's CS2 CAN protocol document (shared/seeds/003_e81750172fa08e9b.txt, chapters
// 1-7 and 9) and the value tables around them, decoded through the typed API, checked against the meaning
// the document gives them, and encoded back to the same bytes. Sections that print no example frame get
// frames built from the section's format table (the test says so). The facts with concrete values from
// shared/docs/cs2-field-notes.md follow at the end (FieldNotes_*).
//
// Example lines are quoted as the document prints them, comment included (parseFrame takes text after
// the data bytes as a comment). All frames use the document's hash 0x4711 unless a test says otherwise.

#include "TestSupport.h"
#include "cs2/Codec.h"
#include "cs2/Crc16.h"
#include "cs2/Fields.h"
#include "cs2/FrameReport.h"
#include "cs2/FrameText.h"
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

using test::corpusFile;
using test::decodeAs;
using test::expectRoundTrip;
using test::frame;

// The decoded message of a frame in document notation; fails the test when it does not decode.
Message decodeText(std::string_view text) {
    const auto result = decode(frame(text));
    EXPECT_TRUE(result.hasValue()) << text << ": " << (result ? "" : result.error().message());
    return result ? *result : Message{};
}

// What describe() shows for one field of a frame: names and text as they are, numbers in decimal,
// flags as true/false; "<none>" when the message has no such field.
std::string described(std::string_view text, std::string_view key) {
    for (const auto& field : describe(decodeText(text))) {
        if (field.key != key)
            continue;
        switch (field.format) {
        case FieldFormat::Text:
            return field.text;
        case FieldFormat::Bool:
            return field.number ? "true" : "false";
        case FieldFormat::Decimal:
        case FieldFormat::Hex:
            break;
        }
        return std::to_string(field.number);
    }
    return "<none>";
}

// The frame must be refused by the decoder with an error of the given kind.
void expectRefused(std::string_view text, DecodeErrorKind kind) {
    const auto result = decode(frame(text));
    ASSERT_FALSE(result.hasValue()) << text << " decoded as " << messageName(result->body);
    EXPECT_EQ(result.error().kind, kind) << text << ": " << result.error().message();
}

bool contains(std::string_view text, std::string_view part) {
    return text.find(part) != std::string_view::npos;
}

// A document-notation frame with the given id and bytes ("00404711 8 6C 6F ...").
std::string frameText(std::string_view id, const std::vector<std::uint8_t>& bytes) {
    static constexpr char Digits[] = "0123456789ABCDEF";
    std::string text = std::string(id) + " " + std::to_string(bytes.size());
    for (auto byte : bytes) {
        text += ' ';
        text += Digits[byte >> 4];
        text += Digits[byte & 0x0F];
    }
    return text;
}

// A config data request (7.1) for a file key, zero padded to eight bytes.
std::string configRequest(std::string_view id, std::string_view key) {
    std::vector<std::uint8_t> bytes(8, 0);
    for (std::size_t i = 0; i < key.size() && i < 8; ++i)
        bytes[i] = std::uint8_t(key[i]);
    return frameText(id, bytes);
}

// ===== 1.2.4 Hash ==================================================================================

TEST(Document_1_2_4_Hash, ExampleHash4711CarriesTheCs2Marker) {
    // All examples use hash 0x4711: bits 7..9 are 0b110, the combination CS1 never uses.
    const CanFrame stop = frame("00004711 5 00 00 00 00 00");
    EXPECT_EQ(cs2::prio(stop), 0);
    EXPECT_EQ(cs2::command(stop), 0x00);
    EXPECT_FALSE(cs2::isResponse(stop));
    EXPECT_EQ(cs2::hash(stop), 0x4711);
    EXPECT_TRUE(hasCs2Marker(cs2::hash(stop)));
}

TEST(Document_1_2_4_Hash, UidHighWordXorLowWordWithCs1BitsSet) {
    // CS2 UID 0x43533208 of the examples: 0x4353 ^ 0x3208 = 0x715B; with bits 7..9 = 0b110: 0x8B5B.
    EXPECT_EQ(hashFromUid(0x43533208u), 0x8B5B);
    EXPECT_TRUE(hasCs2Marker(hashFromUid(0x43533208u)));
}

TEST(Document_1_2_4_Hash, PacketNumberLeavesOutBits7To9) {
    // "Bits 7 bis 9 werden ausgeblendet, die obersten 3 Bits sind 0. Der Wertebereich verringert sich auf
    // 8192."
    EXPECT_EQ(packetNumberFromHash(0x0301), 1);
    EXPECT_EQ(hashFromPacketNumber(1), 0x0301);
    EXPECT_EQ(hashFromPacketNumber(0x7F), 0x037F);
    EXPECT_EQ(hashFromPacketNumber(0x80), 0x0700);
    EXPECT_EQ(hashFromPacketNumber(8191), 0xFF7F);
    for (unsigned packet = 0; packet < 8192; ++packet) {
        const std::uint16_t hash = hashFromPacketNumber(std::uint16_t(packet));
        ASSERT_TRUE(hasCs2Marker(hash)) << packet;
        ASSERT_EQ(packetNumberFromHash(hash), packet);
    }
}

// ===== 1.2.7 CAN over Ethernet ======================================================================

TEST(Document_1_2_7_Ethernet, ThirteenByteDatagram) {
    // Bytes 1-4 the identifier (big endian), byte 5 the DLC, bytes 6-13 the data filled up with 00.
    const CanFrame go = frame("00004711 5 00 00 00 00 01");
    const std::array<std::uint8_t, CanFrame::NetworkSize> datagram{0x00, 0x00, 0x47, 0x11, 0x05, 0x00, 0x00,
                                                                   0x00, 0x00, 0x01, 0x00, 0x00, 0x00};
    EXPECT_EQ(go.toNetwork(), datagram);
    EXPECT_EQ(CanFrame::fromNetwork(datagram), go);
    EXPECT_EQ(formatNetwork(go), "00004711050000000001000000");
    const auto parsed = parseFrame("00004711050000000001000000");
    ASSERT_TRUE(parsed.hasValue());
    EXPECT_EQ(parsed->notation, FrameNotation::Network);
    EXPECT_EQ(parsed->frame, go);
}

// ===== 1.3.1.2 Loc-ID =================================================================================

TEST(Document_1_3_1_2_LocId, MotorolaAddress2) {
    // "Märklin Motorola mit Adresse 2: Basis: 00 00 00 00 Plus Adresse: 00 00 00 02", here in a speed query.
    const auto query = decodeAs<LocoSpeed>("00084711 4 00 00 00 02");
    EXPECT_EQ(query.loco.value(), 0x00000002u);
    EXPECT_EQ(query.loco.range(), LocIdRange::Mm2);
    EXPECT_EQ(query.loco.protocol(), Protocol::Mm2);
    EXPECT_EQ(query.loco.address(), 2u);
    EXPECT_FALSE(query.speed.has_value());
    EXPECT_EQ(LocId::fromAddress(Protocol::Mm2, 2), LocId(0x00000002));
    expectRoundTrip("00084711 4 00 00 00 02");
}

TEST(Document_1_3_1_2_LocId, Mm2AccessoryAddress3) {
    // "MM2 Zubehör mit Adresse 3: Basis: 00 00 30 00 Plus Adresse: 00 00 30 03", here in a switch command.
    // The document counts from 0 here; users count accessories from 1 (field notes), so it is number 4.
    const auto command = decodeAs<AccessorySwitch>("00164711 6 00 00 30 03 01 01");
    EXPECT_EQ(command.article.value(), 0x00003003u);
    EXPECT_EQ(command.article.range(), LocIdRange::Mm2Accessory);
    EXPECT_EQ(command.article.protocol(), Protocol::Mm2Accessory);
    EXPECT_TRUE(command.article.isAccessory());
    EXPECT_EQ(command.article.offset(), 3u);  // the document's "Adresse 3"
    EXPECT_EQ(command.article.address(), 4u); // the 1-based keyboard number
    EXPECT_EQ(LocId::fromAddress(Protocol::Mm2Accessory, 4), LocId(0x3003));
    expectRoundTrip("00164711 6 00 00 30 03 01 01");
}

TEST(Document_1_3_1_2_LocId, AddressSchemeTable) {
    struct Row {
        std::uint32_t start;
        std::uint32_t end;
        LocIdRange range;
        Protocol protocol;
    };
    const Row rows[] = {
        {0x0000, 0x03FF, LocIdRange::Mm2, Protocol::Mm2},
        {0x0400, 0x07FF, LocIdRange::Reserved, Protocol::Other},
        {0x0800, 0x0BFF, LocIdRange::Sx1, Protocol::Sx1},
        {0x0C00, 0x0FFF, LocIdRange::Reserved, Protocol::Other},
        {0x1000, 0x13FF, LocIdRange::Mm2FunctionDecoder, Protocol::Other},
        {0x1400, 0x17FF, LocIdRange::Reserved, Protocol::Other},
        {0x1800, 0x1BFF, LocIdRange::Private, Protocol::Other},
        {0x1C00, 0x1FFF, LocIdRange::Company, Protocol::Other},
        {0x2000, 0x23FF, LocIdRange::Mm2Loco20kHz, Protocol::Other},
        {0x2400, 0x27FF, LocIdRange::Reserved, Protocol::Other},
        {0x2800, 0x2BFF, LocIdRange::Sx1Accessory, Protocol::Sx1Accessory},
        {0x2C00, 0x2FFF, LocIdRange::Traction, Protocol::Other},
        {0x3000, 0x33FF, LocIdRange::Mm2Accessory, Protocol::Mm2Accessory},
        {0x3400, 0x37FF, LocIdRange::Reserved, Protocol::Other},
        {0x3800, 0x3BFF, LocIdRange::DccAccessory, Protocol::DccAccessory},
        {0x3C00, 0x3FFF, LocIdRange::DccAccessory, Protocol::DccAccessory},
        {0x4000, 0x7FFF, LocIdRange::Mfx, Protocol::Mfx},
        {0x8000, 0xBFFF, LocIdRange::Sx2, Protocol::Sx2},
        {0xC000, 0xFFFF, LocIdRange::Dcc, Protocol::Dcc},
    };
    for (const auto& row : rows) {
        SCOPED_TRACE(row.start);
        EXPECT_EQ(LocId(row.start).range(), row.range);
        EXPECT_EQ(LocId(row.end).range(), row.range);
        EXPECT_EQ(LocId(row.start).protocol(), row.protocol);
        EXPECT_EQ(LocId(row.end).protocol(), row.protocol);
    }
    // The two DCC accessory rows form one range of 2048 addresses.
    EXPECT_EQ(LocId(0x3C00).address(), 1025u);
    // Only 0..65535 embed track protocols ("die oberen sind = 0x0000"); above are UIDs.
    EXPECT_EQ(LocId(0x00010000).range(), LocIdRange::DeviceUid);
    EXPECT_EQ(LocId(0x43533208).protocol(), Protocol::Other);
}

// ===== 1.3.2 Feedback and automation ids ============================================================

TEST(Document_1_3_2_2_FeedbackAndAutomationIds, LastS88ContactOfADevice) {
    // 16-bit device id plus 16-bit contact id; S88 contacts: high byte 0..63, low byte 0..255 (16384).
    const auto query = decodeAs<S88Event>("00224711 4 00 05 3F FF");
    EXPECT_EQ(query.device, 0x0005);
    EXPECT_EQ(query.contact, 16383);
    expectRoundTrip("00224711 4 00 05 3F FF");
}

TEST(Document_1_3_2_2_FeedbackAndAutomationIds, A1IsTheFirstMemoryFunction) {
    // Automation functions: high byte 'A' (65), low byte '1' (49, 0x31): "A1", up to "z8".
    EXPECT_EQ(std::uint16_t(('A' << 8) | '1'), 0x4131);
    const auto a1 = decodeAs<AutomationSwitch>("00604711 6 00 05 41 31 01 00");
    EXPECT_EQ(a1.device, 0x0005);
    EXPECT_EQ(a1.function, 0x4131);
    EXPECT_EQ(described("00604711 6 00 05 41 31 01 00", "memory"), "A1");
    EXPECT_EQ(described("00604711 6 00 05 7A 38 01 00", "memory"), "z8");
    expectRoundTrip("00604711 6 00 05 41 31 01 00");
}

// ===== 1.3.3 Speed steps ===========================================================================

// "Systemfahrstufe = 1 + (Gleisfahrstufe - 1) * Schrittweite"; track step 11 as listed, sent as a speed.
void expectTrackStep11(unsigned steps, unsigned width, std::uint16_t systemSpeed, std::string_view text) {
    const auto table = SpeedSteps::forStepCount(steps);
    ASSERT_TRUE(table.has_value());
    EXPECT_EQ(table->stepCount(), steps);
    EXPECT_EQ(table->stepWidth(), width);
    EXPECT_EQ(table->systemSpeed(11), systemSpeed);
    EXPECT_EQ(table->trackStep(systemSpeed), 11u);
    EXPECT_EQ(table->systemSpeed(1), 1); // "Gleisfahrstufe 1 ist somit immer auch Systemfahrstufe 1."
    const auto speed = decodeAs<LocoSpeed>(text);
    EXPECT_EQ(speed.speed, systemSpeed);
    expectRoundTrip(text);
}

TEST(Document_1_3_3_SpeedSteps, Step11Of14Is771) {
    expectTrackStep11(14, 77, 771, "00084711 6 00 00 C0 03 03 03"); // DCC 3, 771 = 0x0303
}

TEST(Document_1_3_3_SpeedSteps, Step11Of27Is381) {
    expectTrackStep11(27, 38, 381, "00084711 6 00 00 00 48 01 7D"); // MM2 72, 381 = 0x017D
}

TEST(Document_1_3_3_SpeedSteps, Step11Of28Is371) {
    expectTrackStep11(28, 37, 371, "00084711 6 00 00 C0 03 01 73"); // DCC 3, 371 = 0x0173
}

TEST(Document_1_3_3_SpeedSteps, Step11Of31Is331) {
    expectTrackStep11(31, 33, 331, "00084711 6 00 00 08 03 01 4B"); // SX1 3, 331 = 0x014B
}

TEST(Document_1_3_3_SpeedSteps, Step11Of126Is81) {
    expectTrackStep11(126, 8, 81, "00084711 6 00 00 C0 03 00 51"); // DCC 3, 81 = 0x0051
}

TEST(Document_1_3_3_SpeedSteps, ValuesAbove1000MeanMaximum) {
    // "Werte oberhalb 1000 (bis 1023) dürfen vorkommen ... Die Fahrgeschwindigkeit entspricht hierbei dem
    // Maximum."
    EXPECT_EQ(effectiveSystemSpeed(1000), 1000);
    EXPECT_EQ(effectiveSystemSpeed(1023), 1000);
    EXPECT_EQ(SpeedSteps::forStepCount(28)->trackStep(1023), 28u);
    EXPECT_FALSE(SpeedSteps::forStepCount(15).has_value()); // not in the table
    const auto speed = decodeAs<LocoSpeed>("00084711 6 00 00 C0 03 03 FF");
    EXPECT_EQ(speed.speed, 1023);
    expectRoundTrip("00084711 6 00 00 C0 03 03 FF");
}

// ===== 1.4 Overview of command values =============================================================

TEST(Document_1_4_CommandOverview, ValueInCanId) {
    // "Wert in CAN-ID" is the second identifier byte: command << 1 with the response bit clear.
    struct Row {
        std::uint8_t command;
        std::uint8_t inCanId;
        std::string_view name;
    };
    const Row rows[] = {
        {0x01, 0x02, "loco.discovery"},     {0x02, 0x04, "mfx.bind"},
        {0x03, 0x06, "mfx.verify"},         {0x04, 0x08, "loco.speed"},
        {0x05, 0x0A, "loco.direction"},     {0x06, 0x0C, "loco.function"},
        {0x07, 0x0E, "config.read"},        {0x08, 0x10, "config.write"},
        {0x0B, 0x16, "accessory.switch"},   {0x0C, 0x18, "accessory.config"},
        {0x10, 0x20, "feedback.s88-poll"},  {0x11, 0x22, "feedback.s88-event"},
        {0x12, 0x24, "feedback.sx1-event"}, {0x18, 0x30, "ping"},
        {0x19, 0x32, "update.offer"},       {0x1A, 0x34, "update.read-config-data"},
        {0x1B, 0x36, "bootloader.can"},     {0x1C, 0x38, "bootloader.track"},
        {0x1D, 0x3A, "statusdata.config"},  {0x20, 0x40, "configdata.request"},
        {0x21, 0x42, "configdata.stream"},  {0x22, 0x44, "connect6021.stream"},
        {0x30, 0x60, "automation.switch"}, // from 9.1
    };
    for (const auto& row : rows) {
        SCOPED_TRACE(row.name);
        const CanFrame f{cs2::makeId(0, row.command, false, 0x4711), 0, {}};
        EXPECT_EQ(cs2::command(f), row.command);
        EXPECT_EQ(f.toNetwork()[1], row.inCanId);
        EXPECT_EQ(intendedName(f), row.name);
    }
}

TEST(Document_1_4_CommandOverview, SystemSubcommandValues) {
    struct Row {
        std::uint8_t sub;
        std::string_view name;
    };
    const Row rows[] = {
        {0x00, "system.stop"},
        {0x01, "system.go"},
        {0x02, "system.halt"},
        {0x03, "system.loco-emergency-stop"},
        {0x04, "system.loco-cycle-end"},
        {0x05, "system.loco-protocol"},
        {0x06, "system.accessory-switch-time"},
        {0x07, "system.mfx-fast-read"},
        {0x08, "system.track-protocols"},
        {0x09, "system.mfx-registration-counter"},
        {0x0A, "system.overload"},
        {0x0B, "system.status"},
        {0x0C, "system.device-id"},
        {0x30, "system.mfx-seek"},
        {0x80, "system.reset"},
    };
    for (const auto& row : rows) {
        SCOPED_TRACE(row.name);
        CanFrame f{cs2::makeId(0, 0x00, false, 0x4711), 5, {}};
        f.data[4] = row.sub;
        EXPECT_EQ(intendedName(f), row.name);
    }
}

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
    const auto bytesOnly = parseFrame("00004711 7 00 00 00 00 06 0A");
    ASSERT_FALSE(bytesOnly.hasValue());
    EXPECT_TRUE(contains(bytesOnly.error(), "DLC 7 announces 7 data bytes, only 6 given"))
        << bytesOnly.error();
    // As printed, with its comment: the comment's first word stands where the seventh byte should be.
    const auto asPrinted = parseFrame("00004711 7 00 00 00 00 06 0A Schaltzeit 100 ms festlegen");
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

// ===== Field notes: framing ==========================================================================

TEST(FieldNotes_Framing, NetworkFormByteLayout) {
    // byte 0 = prio << 1 | command >> 7, byte 1 = command << 1 | response, bytes 2-3 hash, byte 4 DLC.
    const CanFrame f{cs2::makeId(3, 0x21, true, 0x0301), 8, {1, 2, 3, 4, 5, 6, 7, 8}};
    const auto bytes = f.toNetwork();
    EXPECT_EQ(bytes[0], 0x06);
    EXPECT_EQ(bytes[1], 0x43);
    EXPECT_EQ(bytes[2], 0x03);
    EXPECT_EQ(bytes[3], 0x01);
    EXPECT_EQ(bytes[4], 8);
    EXPECT_EQ(bytes[12], 8);
}

TEST(FieldNotes_Framing, DlcAbove8IsRefused) {
    std::array<std::uint8_t, CanFrame::NetworkSize> bytes{0x00, 0x00, 0x47, 0x11, 0x09};
    const auto result = decode(CanFrame::fromNetwork(bytes));
    ASSERT_FALSE(result.hasValue());
    EXPECT_EQ(result.error().kind, DecodeErrorKind::DlcOutOfRange);
    EXPECT_TRUE(contains(result.error().message(), "DLC 9 is above 8")) << result.error().message();
}

// ===== Field notes: addresses ========================================================================

TEST(FieldNotes_Addresses, MmAccessory1Is0x3000) {
    EXPECT_EQ(LocId::fromAddress(Protocol::Mm2Accessory, 1), LocId(0x3000));
    EXPECT_EQ(LocId(0x3000).address(), 1u);
    EXPECT_EQ(LocId::fromAddress(Protocol::Mm2Accessory, 1024), LocId(0x33FF));
    EXPECT_FALSE(LocId::fromAddress(Protocol::Mm2Accessory, 0).has_value());
    EXPECT_EQ(described("00164711 6 00 00 30 00 01 01", "address"), "1");
    expectRoundTrip("00164711 6 00 00 30 00 01 01");
}

TEST(FieldNotes_Addresses, DccAccessory1Is0x3800) {
    EXPECT_EQ(LocId::fromAddress(Protocol::DccAccessory, 1), LocId(0x3800));
    EXPECT_EQ(LocId(0x3800).address(), 1u);
    EXPECT_EQ(LocId::fromAddress(Protocol::DccAccessory, 2048), LocId(0x3FFF));
    EXPECT_FALSE(LocId::fromAddress(Protocol::DccAccessory, 0).has_value());
    EXPECT_EQ(described("00164711 6 00 00 38 00 01 01", "address"), "1");
}

TEST(FieldNotes_Addresses, DocumentsMm2Accessory3CountsFromZero) {
    // The document's "MM2 Zubehör mit Adresse 3" = 0x3003 is offset 3, keyboard number 4.
    EXPECT_EQ(LocId(0x3003).offset(), 3u);
    EXPECT_EQ(LocId(0x3003).address(), 4u);
    EXPECT_EQ(described("00164711 6 00 00 30 03 01 01", "address"), "4");
}

TEST(FieldNotes_Addresses, LocoAddressesAreOffsetsFromTheRangeBase) {
    EXPECT_EQ(LocId::fromAddress(Protocol::Mm2, 72), LocId(0x0048));
    EXPECT_EQ(LocId::fromAddress(Protocol::Dcc, 3), LocId(0xC003));
    EXPECT_EQ(LocId::fromAddress(Protocol::Mfx, 5), LocId(0x4005));
    EXPECT_EQ(LocId::fromAddress(Protocol::Sx1, 3), LocId(0x0803));
}

// ===== Field notes: hash ============================================================================

TEST(FieldNotes_Hash, CommonImplementationFormula) {
    // x = uid_hi16 ^ uid_lo16; ((x << 3) & 0xFF00) | 0x0300 | (x & 0x7F).
    for (std::uint32_t uid : {0x00000000u, 0x43533208u, 0x4743F5DAu, 0xFFFA8C43u, 0x12345678u, 0xFFFFFFFFu}) {
        const std::uint16_t x = std::uint16_t((uid >> 16) ^ (uid & 0xFFFF));
        const std::uint16_t expected = std::uint16_t(((x << 3) & 0xFF00) | 0x0300 | (x & 0x7F));
        EXPECT_EQ(hashFromUid(uid), expected) << std::hex << uid;
        EXPECT_TRUE(hasCs2Marker(hashFromUid(uid)));
    }
}

TEST(FieldNotes_Hash, HashesWithoutMarkerStillDecode) {
    // MS2s send plain x, and answer loco streams with hash 0: never validate a peer's hash.
    EXPECT_FALSE(hasCs2Marker(0x0000));
    EXPECT_FALSE(hasCs2Marker(0x715B));
    Message envelope;
    const auto speed = decodeAs<LocoSpeed>("0009715B 6 00 00 40 05 01 F4", &envelope);
    EXPECT_EQ(envelope.hash, 0x715B);
    EXPECT_EQ(speed.speed, 500);
    EXPECT_EQ(decodeAs<LocoSpeed>("00090000 4 00 00 40 05").loco.value(), 0x00004005u);
    expectRoundTrip("0009715B 6 00 00 40 05 01 F4");
}

// ===== Field notes: config data =======================================================================

TEST(FieldNotes_ConfigData, RequestKeysAreZeroPadded) {
    // The notes list "lokstat" where the document's table says "loksstat"; both are just eight bytes.
    for (std::string_view key :
         {"loks", "mags", "fs", "gbs", "gbs-2", "lokstat", "loksstat", "magstat", "gbsstat"}) {
        const std::string text = configRequest("00404711", key);
        SCOPED_TRACE(text);
        const auto request = decodeAs<ConfigDataRequest>(text);
        EXPECT_EQ(request.text(), key);
        for (std::size_t i = key.size(); i < 8; ++i)
            EXPECT_EQ(request.filename[i], '\0');
        expectRoundTrip(text);
    }
}

TEST(FieldNotes_ConfigData, LoknamenFollowUpFrame) {
    // "loknamen" needs a second frame with ASCII "<first> <count>", here the first two locos.
    EXPECT_EQ(decodeAs<ConfigDataRequest>(configRequest("00404711", "loknamen")).text(), "loknamen");
    EXPECT_EQ(decodeAs<ConfigDataRequest>(configRequest("00404711", "0 2")).text(), "0 2");
    expectRoundTrip(configRequest("00404711", "0 2"));
}

TEST(FieldNotes_ConfigData, LokinfoNameInTwoFrames) {
    // "lokinfo" is followed by two frames carrying a 16-character loco name; full frames have no NUL.
    const std::string first = configRequest("00404711", "Dampflok");
    const std::string second = configRequest("00404711", " BR 01.1");
    EXPECT_EQ(std::string(decodeAs<ConfigDataRequest>(first).text()) +
                  std::string(decodeAs<ConfigDataRequest>(second).text()),
              "Dampflok BR 01.1");
    expectRoundTrip(first);
    expectRoundTrip(second);
}

TEST(FieldNotes_ConfigData, CrcCheckValue) {
    // CCITT-FALSE check value: "123456789" -> 0x29B1.
    const std::string_view check = "123456789";
    std::vector<std::uint8_t> bytes(check.begin(), check.end());
    EXPECT_EQ(crc16(bytes), 0x29B1);
}

TEST(FieldNotes_ConfigData, CorpusStreamTestVector) {
    // can2udp's logged stream: header DLC 7 (length 0x5F, CRC 0x2170, 0x7B), then 12 data frames.
    std::ifstream in(corpusFile("GBert__railroad/can2udp/src/example_zlib.txt"));
    ASSERT_TRUE(in.is_open());
    std::vector<CanFrame> frames;
    for (std::string line; std::getline(in, line);) {
        if (line.find_first_not_of(" \t\r") == std::string::npos)
            continue;
        const auto parsed = parseFrame(line);
        ASSERT_TRUE(parsed.hasValue()) << line << ": " << parsed.error();
        frames.push_back(parsed->frame);
    }
    ASSERT_EQ(frames.size(), 13u);

    const auto header = decode(frames[0]);
    ASSERT_TRUE(header.hasValue());
    const auto* head = std::get_if<ConfigDataStream>(&header->body);
    ASSERT_NE(head, nullptr);
    EXPECT_EQ(head->form, ConfigDataStream::Form::BroadcastHeader);
    EXPECT_EQ(head->length, 0x5Fu);
    EXPECT_EQ(head->crc, 0x2170);
    EXPECT_EQ(head->extra, 0x7B);
    EXPECT_EQ(header->hash, 0x0300);
    EXPECT_EQ(encode(*header), frames[0]);

    std::vector<std::uint8_t> payload;
    for (std::size_t i = 1; i < frames.size(); ++i) {
        const auto result = decode(frames[i]);
        ASSERT_TRUE(result.hasValue()) << i;
        const auto* data = std::get_if<ConfigDataStream>(&result->body);
        ASSERT_NE(data, nullptr) << i;
        EXPECT_EQ(data->form, ConfigDataStream::Form::Data);
        payload.insert(payload.end(), data->data.begin(), data->data.end());
        EXPECT_EQ(encode(*result), frames[i]) << i;
    }
    ASSERT_EQ(payload.size(), 96u);
    EXPECT_EQ(crc16(payload), 0x2170);
    EXPECT_EQ(crc16(std::span(payload.data(), 95)), 0x772F);
    // Compressed payload: u32 BE uncompressed size (170), then a zlib stream (78 9C).
    EXPECT_EQ((payload[0] << 24) | (payload[1] << 16) | (payload[2] << 8) | payload[3], 170);
    EXPECT_EQ(payload[4], 0x78);
    EXPECT_EQ(payload[5], 0x9C);
}

// ===== Field notes: status data and readings =========================================================

TEST(FieldNotes_StatusData, PacketHashesAndEndFrames) {
    // Data frames: hash 0x0300 + packet number, first packet 0x0301.
    for (std::uint16_t packet = 1; packet <= 3; ++packet)
        EXPECT_EQ(hashFromPacketNumber(packet), 0x0300 + packet);
    // End frame DLC 6 with the count; some devices send DLC 5 without it.
    const auto withCount = decodeAs<StatusDataConfig>("003B4711 6 47 43 F5 DA 00 04");
    EXPECT_EQ(withCount.form, StatusDataConfig::Form::End);
    EXPECT_EQ(withCount.packetCount, 4);
    const auto withoutCount = decodeAs<StatusDataConfig>("003B4711 5 47 43 F5 DA 00");
    EXPECT_EQ(withoutCount.form, StatusDataConfig::Form::End);
    EXPECT_EQ(withoutCount.device, 0x4743F5DAu);
    EXPECT_FALSE(withoutCount.packetCount.has_value());
    expectRoundTrip("003B4711 6 47 43 F5 DA 00 04");
    expectRoundTrip("003B4711 5 47 43 F5 DA 00");
    // A shorter last data frame is still a packet.
    const auto shortLast = decodeAs<StatusDataConfig>("003B0305 3 41 00 00");
    EXPECT_EQ(shortLast.form, StatusDataConfig::Form::Packet);
    EXPECT_EQ(shortLast.packet.size, 3);
    expectRoundTrip("003B0305 3 41 00 00");
}

TEST(FieldNotes_StatusData, Gleisbox60113PingAnswer) {
    // Gleisbox 60113: UID 0x4743F5DA, device type 0x0010 (the version bytes here are illustrative).
    const std::string text = "00314711 8 47 43 F5 DA 01 27 00 10";
    const auto ping = decodeAs<Ping>(text);
    ASSERT_TRUE(ping.identity.has_value());
    EXPECT_EQ(ping.identity->uid, 0x4743F5DAu);
    EXPECT_EQ(ping.identity->deviceType, 0x0010);
    EXPECT_EQ(described(text, "deviceName"), "Gleisbox 60112/60113");
    expectRoundTrip(text);
}

// One reading description of the field notes' Gleisbox 60113, as the status-data stream carries it.
struct ReadingDescription {
    std::uint8_t channel;
    std::int8_t power;
    std::uint16_t zero;
    std::array<std::uint16_t, 4> ends;
    std::string name, start, end, unit;
};

std::vector<std::uint8_t> serialise(const ReadingDescription& d) {
    std::vector<std::uint8_t> out{d.channel, std::uint8_t(d.power), 0x30, 0xF0, 0xE0,
                                  0xC0}; // colours illustrative
    auto u16 = [&](std::uint16_t v) {
        out.push_back(std::uint8_t(v >> 8));
        out.push_back(std::uint8_t(v));
    };
    u16(d.zero);
    for (auto e : d.ends)
        u16(e);
    for (const auto* s : {&d.name, &d.start, &d.end, &d.unit}) {
        out.insert(out.end(), s->begin(), s->end());
        out.push_back(0);
    }
    return out;
}

// Sends the bytes as status-data packets (hash = packet number), decodes them back and reassembles.
std::vector<std::uint8_t> throughPackets(const std::vector<std::uint8_t>& bytes) {
    std::vector<std::uint8_t> out;
    for (std::size_t offset = 0, packet = 1; offset < bytes.size(); offset += 8, ++packet) {
        std::vector<std::uint8_t> chunk(8, 0);
        std::copy(bytes.begin() + long(offset), bytes.begin() + long(std::min(bytes.size(), offset + 8)),
                  chunk.begin());
        char id[9];
        std::snprintf(id, sizeof id, "003B%04X", hashFromPacketNumber(std::uint16_t(packet)));
        const std::string text = frameText(id, chunk);
        Message envelope;
        const auto decoded = decodeAs<StatusDataConfig>(text, &envelope);
        EXPECT_EQ(decoded.form, StatusDataConfig::Form::Packet) << text;
        EXPECT_EQ(packetNumberFromHash(envelope.hash), packet) << text;
        const auto view = decoded.packet.view();
        out.insert(out.end(), view.begin(), view.end());
    }
    return out;
}

// Displayed value = start + (raw - zero) * (end - start) / (rangeEnd4 - zero).
double displayed(const std::vector<std::uint8_t>& description, std::uint16_t raw) {
    auto u16 = [&](std::size_t i) { return std::uint16_t((description[i] << 8) | description[i + 1]); };
    const std::uint16_t zero = u16(6);
    const std::uint16_t end4 = u16(14);
    std::vector<std::string> strings;
    std::string current;
    for (std::size_t i = 16; i < description.size() && strings.size() < 4; ++i) {
        if (description[i] == 0) {
            strings.push_back(current);
            current.clear();
        } else {
            current.push_back(char(description[i]));
        }
    }
    const double start = std::stod(strings.at(1));
    const double end = std::stod(strings.at(2));
    return start + (double(raw) - zero) * (end - start) / (double(end4) - zero);
}

TEST(FieldNotes_StatusData, Gleisbox60113ReadingsScale) {
    const ReadingDescription track{1,       -3,     0x000F, {0x0670, 0x06C2, 0x0767, 0x080C},
                                   "TRACK", "0.00", "2.50", "A"};
    const ReadingDescription volt{3,      -3,      0x0000,  {0x039D, 0x04B2, 0x0A1E, 0x0C49},
                                  "VOLT", "10.00", "27.00", "Volt"};
    const ReadingDescription temp{4, 0, 0x0000, {0x006B, 0x00A4, 0x00CD, 0x00DB}, "TEMP", "0.0", "80.0", "C"};

    // The readings arrive as system status answers (2.12) on the description's query channel.
    const auto current = decodeAs<SystemStatus>("00014711 8 47 43 F5 DA 0B 01 00 2E");
    EXPECT_EQ(current.device, 0x4743F5DAu);
    EXPECT_EQ(current.channel, track.channel);
    ASSERT_TRUE(current.value.has_value());
    EXPECT_EQ(*current.value, 46);
    const auto voltage = decodeAs<SystemStatus>("00014711 8 47 43 F5 DA 0B 03 08 81");
    EXPECT_EQ(voltage.channel, volt.channel);
    EXPECT_EQ(voltage.value, 2177);
    const auto temperature = decodeAs<SystemStatus>("00014711 8 47 43 F5 DA 0B 04 00 28");
    EXPECT_EQ(temperature.channel, temp.channel);
    EXPECT_EQ(temperature.value, 40);

    const auto trackBytes = throughPackets(serialise(track));
    EXPECT_EQ(trackBytes.size() % 8, 0u);
    EXPECT_NEAR(displayed(trackBytes, *current.value), 0.038, 0.0005);
    EXPECT_NEAR(displayed(throughPackets(serialise(volt)), voltage.value.value_or(0)), 21.8, 0.05);
    EXPECT_NEAR(displayed(throughPackets(serialise(temp)), temperature.value.value_or(0)), 14.6, 0.05);
}

TEST(FieldNotes_StatusData, WriteConfigValueAndAnswer) {
    // System 0x0B: DLC 8 without response bit writes a config value; the answer is DLC 7 with 1 or 0.
    Message envelope;
    const auto write = decodeAs<SystemStatus>("00004711 8 47 43 F5 DA 0B 05 01 F4", &envelope);
    EXPECT_FALSE(envelope.response);
    EXPECT_EQ(write.value, 500);
    EXPECT_EQ(decodeAs<SystemStatus>("00014711 7 47 43 F5 DA 0B 05 01").accepted, true);
    EXPECT_EQ(decodeAs<SystemStatus>("00014711 7 47 43 F5 DA 0B 05 00").accepted, false);
}

// ===== Field notes: devices and start-up ============================================================

TEST(FieldNotes_Devices, PingDeviceTypesSeen) {
    EXPECT_EQ(deviceTypeName(0x0011), "Gleisbox 60116");
    for (std::uint16_t ms2 = 0x0030; ms2 <= 0x0034; ++ms2)
        EXPECT_EQ(deviceTypeName(ms2), "Mobile Station 2") << ms2;
    EXPECT_EQ(deviceTypeName(0x0040), "Link S88");
    EXPECT_EQ(deviceTypeName(0xEEEE), "CS2 software (PC)");
    EXPECT_EQ(deviceTypeName(0x1234), "unknown device type");
}

TEST(FieldNotes_Devices, GleisboxGoFrame) {
    // can2lan wakes a bare Gleisbox with "0x1B DLC5 00 00 00 00 11": CAN bootloader, UID 0, 0x11 = go.
    const std::string go = "00364711 5 00 00 00 00 11";
    Message envelope;
    const auto boot = decodeAs<BootloaderCan>(go, &envelope);
    EXPECT_FALSE(envelope.response);
    EXPECT_EQ(boot.raw.size, 5);
    EXPECT_EQ(boot.raw.bytes[4], 0x11);
    EXPECT_EQ(described(go, "uid"), "0");
    EXPECT_EQ(described(go, "mode"), "start-application");
    expectRoundTrip(go);
    // ... then system 0x08 with 0x07: enable MM2, mfx and DCC.
    const auto enable = decodeAs<TrackProtocols>("00004711 6 00 00 00 00 08 07");
    EXPECT_EQ(enable.target, 0x00000000u);
    EXPECT_EQ(enable.mask, 0x07);
    EXPECT_EQ(described("00004711 6 00 00 00 00 08 07", "protocols"), "mm2,mfx,dcc");
    expectRoundTrip("00004711 6 00 00 00 00 08 07");
}

// ===== Field notes: S88 feedback =====================================================================

TEST(FieldNotes_S88, EventAnswerFields) {
    // Device id, contact, old state, new state, time in 10 ms units; Link-S88 buses count contacts by
    // thousands (contact 1001 = bus 1, contact 1).
    const std::string text = "00234711 8 00 40 03 E9 01 00 01 2C";
    const auto event = decodeAs<S88Event>(text);
    EXPECT_EQ(event.device, 0x0040);
    EXPECT_EQ(event.contact, 1001);
    ASSERT_TRUE(event.change.has_value());
    EXPECT_EQ(event.change->oldState, 1);
    EXPECT_EQ(event.change->newState, 0);
    EXPECT_EQ(event.change->time10ms, 300);
    EXPECT_EQ(described(text, "timeMs"), "3000");
    expectRoundTrip(text);
}

} // namespace
} // namespace stellwerk::cs2
