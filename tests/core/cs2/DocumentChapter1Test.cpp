// The examples of Märklin's CS2 CAN protocol document (shared/seeds/003_e81750172fa08e9b.txt) in chapter 1
// (hash, CAN over Ethernet, Loc-IDs, feedback ids, speed steps, the command overview), decoded through the
// typed API, checked against the meaning the document gives them, and encoded back to the same bytes.
// Sections that print no example frame get frames built from the section's format table (the test says so).
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

using test::decodeAs;
using test::described;
using test::expectRoundTrip;
using test::frame;

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
    const auto parsed = can::parseFrame("00004711050000000001000000");
    ASSERT_TRUE(parsed.hasValue());
    EXPECT_EQ(parsed->notation, can::FrameNotation::Network);
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

} // namespace
} // namespace stellwerk::cs2
