// The only example payloads of the RO document (004 §3.3, §3.4), its register byte-order tables (§2.2)
// and, marked Derived, the answers the notes (B4.4) work out, since the document prints none.
#include "ro/Codec.h"
#include "ro/RegisterFile.h"

#include <gtest/gtest.h>
#include <vector>

namespace stellwerk::ro {
namespace {

std::vector<std::uint8_t> bytesOf(const Payload& payload) {
    return {payload.bytes.begin(), payload.bytes.begin() + payload.size};
}

using Bytes = std::vector<std::uint8_t>;

// 004 §3.3 "Beispiel für ein Schreibbefehl": address 0012 hex, value 0F hex, job 0x34, COMMAND 0x12.
TEST(RoDocument, Section3_3_WriteCommandExample) {
    const Bytes document{0x12, 0x12, 0x00, 0x34, 0x0F, 0x00, 0x00, 0x00};
    const Request request{Request::Kind::Write, Width::Byte, 0x0012, 0x34, 0x0F};
    EXPECT_EQ(bytesOf(encode(request)), document);

    const auto decoded = decodeRequest(document);
    ASSERT_TRUE(decoded) << decoded.error().reason;
    EXPECT_EQ(*decoded, request);
    EXPECT_EQ(decoded->name(), "ro.write-byte");
}

// 004 §3.4 "Beispiel für das Beschreiben der ersten 16 Relais": relays 1-13 off, 14 on, 15 and 16 off.
TEST(RoDocument, Section3_4_FirstSixteenRelaysExample) {
    const Bytes document{0x13, 0x00, 0x00, 0x35, 0x00, 0x20, 0x00, 0x00};
    const Request request{Request::Kind::Write, Width::Word, 0x0000, 0x35, 0x2000};
    EXPECT_EQ(bytesOf(encode(request)), document);

    const auto decoded = decodeRequest(document);
    ASSERT_TRUE(decoded) << decoded.error().reason;
    EXPECT_EQ(*decoded, request);
    // Relay n is bit n-1 of the little-endian word at 0x0000: only relay 14 is on.
    for (unsigned relay = 1; relay <= 16; ++relay)
        EXPECT_EQ((decoded->value >> (relay - 1)) & 1u, relay == 14 ? 1u : 0u) << "relay " << relay;
}

// 004 §2.2 "Tabelle mit Aufteilung in 8,16,32 Bit Registerzugriff": which addresses an access covers.
TEST(RoDocument, Section2_2_AccessWidthTable) {
    struct Row {
        Width width;
        std::uint16_t address;
        Bytes covered;
    };
    const Row rows[] = {{Width::Byte, 0x0000, {0}},
                        {Width::Word, 0x0000, {0, 1}},
                        {Width::Long, 0x0000, {0, 1, 2, 3}},
                        {Width::Long, 0x0004, {4, 5, 6, 7}}};
    for (const Row& row : rows) {
        RegisterFile registers;
        ASSERT_TRUE(registers.write(row.address, row.width, 0xFFFFFFFF));
        for (std::uint16_t address = 0; address < 8; ++address) {
            const bool covered =
                std::find(row.covered.begin(), row.covered.end(), address) != row.covered.end();
            EXPECT_EQ(registers.byteAt(address), covered ? 0xFF : 0x00)
                << widthName(row.width) << " at " << row.address << ", byte " << address;
        }
    }
}

// 004 §2.2 "Byte-Reihenfolge der Daten im Register": little endian, the low byte at the address.
TEST(RoDocument, Section2_2_ByteOrderTable) {
    struct Row {
        Width width;
        std::uint16_t address;
        std::uint32_t value;
        Bytes memory; // bytes 00..07 after the write
    };
    const Row rows[] = {{Width::Byte, 0x04, 0x1A, {0, 0, 0, 0, 0x1A, 0, 0, 0}},
                        {Width::Word, 0x06, 0x1A1B, {0, 0, 0, 0, 0, 0, 0x1B, 0x1A}},
                        {Width::Long, 0x00, 0x01020304, {0x04, 0x03, 0x02, 0x01, 0, 0, 0, 0}},
                        {Width::Long, 0x04, 0x01020304, {0, 0, 0, 0, 0x04, 0x03, 0x02, 0x01}}};
    for (const Row& row : rows) {
        RegisterFile registers;
        ASSERT_TRUE(registers.write(row.address, row.width, row.value));
        Bytes memory;
        for (std::uint16_t address = 0; address < 8; ++address)
            memory.push_back(registers.byteAt(address));
        EXPECT_EQ(memory, row.memory) << widthName(row.width) << " at " << row.address;
        EXPECT_EQ(registers.read(row.address, row.width), row.value);
    }
}

// 004 §3.5.2.1, the table of read widths: answer data bytes per read COMMAND.
TEST(RoDocument, Section3_5_2_1_ReadAnswerByteCounts) {
    EXPECT_EQ(byteCount(Width::Bit), 1u);  // 0x21
    EXPECT_EQ(byteCount(Width::Byte), 1u); // 0x22
    EXPECT_EQ(byteCount(Width::Word), 2u); // 0x23
    EXPECT_EQ(byteCount(Width::Long), 4u); // 0x24
}

// Derived (notes B4.4): OK answers to the §3.3 and §3.4 writes, 7 bytes with width code 0 "Keine Daten".
TEST(RoDerived, OkAnswersToTheDocumentsWrites) {
    EXPECT_EQ(bytesOf(encode(Answer(OkAnswer{Width::None, 0x34, 0}))), (Bytes{0x01, 0x00, 0x34, 0, 0, 0, 0}));
    const Bytes toRelays{0x01, 0x00, 0x35, 0, 0, 0, 0};
    const auto decoded = decodeAnswer(toRelays);
    ASSERT_TRUE(decoded) << decoded.error().reason;
    EXPECT_EQ(*decoded, Answer(OkAnswer{Width::None, 0x35, 0}));
}

// Derived (notes B4.4): 0xFD with the job id (2 bytes); 0xFE alone, no job id (1 byte).
TEST(RoDerived, DuplicateJobAndInvalidCommandAnswers) {
    EXPECT_EQ(bytesOf(encode(Answer(DuplicateJobAnswer{0x35}))), (Bytes{0xFD, 0x35}));
    EXPECT_EQ(bytesOf(encode(Answer(InvalidCommandAnswer{}))), (Bytes{0xFE}));
    const auto duplicate = decodeAnswer(Bytes{0xFD, 0x35});
    ASSERT_TRUE(duplicate);
    EXPECT_EQ(std::get<DuplicateJobAnswer>(*duplicate).job, 0x35);
    EXPECT_TRUE(decodeAnswer(Bytes{0xFE}));
    // The request that earns it: COMMAND 0x30 is none of 0x11-0x14 / 0x21-0x24.
    EXPECT_FALSE(decodeRequest(Bytes{0x30, 0, 0, 0x36, 0, 0, 0, 0}));
}

// Derived (notes B4.4): reading the relay word back after §3.4, job 0x36; 8 bytes by default, 4 with the
// profile option; the answer carries width code 3 (word) and 0x2000 little endian.
TEST(RoDerived, ReadWordAfterTheRelayExample) {
    const Request read{Request::Kind::Read, Width::Word, 0x0000, 0x36};
    EXPECT_EQ(bytesOf(encode(read)), (Bytes{0x23, 0x00, 0x00, 0x36, 0, 0, 0, 0}));
    EXPECT_EQ(bytesOf(encode(read, ReadRequestSize::Four)), (Bytes{0x23, 0x00, 0x00, 0x36}));
    EXPECT_EQ(decodeRequest(Bytes{0x23, 0x00, 0x00, 0x36}).value(), read);

    const Bytes answer{0x01, 0x03, 0x36, 0x00, 0x20, 0x00, 0x00};
    EXPECT_EQ(bytesOf(encode(Answer(OkAnswer{Width::Word, 0x36, 0x2000}))), answer);
    EXPECT_EQ(decodeAnswer(answer).value(), Answer(OkAnswer{Width::Word, 0x36, 0x2000}));
}

} // namespace
} // namespace stellwerk::ro
