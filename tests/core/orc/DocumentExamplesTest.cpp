// The document's two worked examples (001 §B) CAN Devices: the UID of 'Michael F. Schwarzer';
// §Genereller Aufbau der Befehle: MM2 Weiche 5 = Ziel Id 0x3005) and the notes' derived vectors V1-V10
// (notes A4.2, "Derived": not printed in the document; they pin layout L2 and the decisions).

#include "can/FrameText.h"
#include "orc/Codec.h"
#include "orc/Uid.h"

#include <gtest/gtest.h>

using namespace stellwerk;
using namespace stellwerk::orc;

namespace {

can::CanFrame frame(std::string_view text) {
    const auto parsed = can::parseFrame(text);
    EXPECT_TRUE(bool(parsed)) << text;
    return parsed ? parsed->frame : can::CanFrame{};
}

constexpr Origin Central{prio::Safety, 0, 0x0000};
constexpr Origin CentralControl{prio::Control, 0, 0x0000};
constexpr Origin CentralManagement{prio::Management, 0, 0x0000};

struct Vector {
    std::string_view name;
    std::string_view frame; // document notation: id, DLC, data
    Message message;
};

// Notes A4.2, Derived: central = bus id 0x0000, type 0; priorities as in notes A1.4.
const Vector Derived[] = {
    {"V1 Alles Aus, whole system", "09000000 1 00", AllOff{Central, Target::all()}},
    {"V2 Alles EIN, device 0x2E01", "09000000 3 01 2E 01", AllOn{Central, Target::busId(0x2E01)}},
    {"V3 Ueberlast port 2, current, booster 0x0042", "09000042 3 0A 01 02",
     Overload{{prio::Safety, 0, 0x0042}, false, 1, true, 2}},
    {"V4 Lok Nothalt, all", "09020000 1 00", LocoStop{Central, Target::all()}},
    {"V5 dekoder schalten MM2 Weiche 5, Pos 1", "11100000 4 03 30 05 01",
     DecoderSwitch{CentralControl, false, 0x3005, 1}},
    {"V6 Lok Speed query MM loco 72", "11020000 3 01 00 48", LocoSpeedQuery{CentralControl, 0x0048}},
    {"V7 Lok Speed answer 0x0048, speed 500", "11030000 5 01 00 48 01 F4",
     LocoSpeed{CentralControl, true, 0x0048, 500}},
    {"V8 Enkoder Status event, encoder 0x2E01, inputs 0 and 2", "17122E01 4 10 2E 01 05",
     EncoderStatus{{prio::Control, 3, 0x2E01}, false, 0x2E01, 1, 0x05}},
    {"V9 Ping UID 0x3A2E2E01", "19200000 5 00 3A 2E 2E 01", Ping{CentralManagement, 0x3A2E2E01}},
    {"V10 Ping answer from CAN decoder 0x2E01, Vers 0x0102", "1D212E01 7 00 3A 2E 2E 01 01 02",
     PingAnswer{{prio::Management, 2, 0x2E01}, 0x3A2E2E01, 0x0102}},
};

} // namespace

// 001 §B) CAN Devices: 'S' 0x53 XOR 'i' 0x69 = 0x3A, 'c' 0x63 XOR 'M' 0x4D = 0x2E: Word1 = 0x3A2E.
TEST(BCanDevices, UidWord1OfMichaelFSchwarzerIs0x3A2E) {
    EXPECT_EQ(developerWord("Michael", "Schwarzer"), std::optional<std::uint16_t>(0x3A2E));
    EXPECT_EQ(makeUid(0x3A2E, 0x2E01), 0x3A2E2E01u);
    EXPECT_EQ(wantedBusId(0x3A2E2E01), 0x2E01);
}

TEST(BCanDevices, UidRuleIsCaseSensitiveAsPrintedAndNeedsTwoLetters) {
    EXPECT_NE(developerWord("michael", "schwarzer"), std::optional<std::uint16_t>(0x3A2E));
    EXPECT_FALSE(developerWord("M", "Schwarzer").has_value());
    EXPECT_FALSE(developerWord("Michael", "S").has_value());
}

// 001 §Bus ID Vergabe: a bus id that is taken: "zählt die Zentrale einfach 'hoch'".
TEST(BusIdVergabe, TakenBusIdCountsUpAndWraps) {
    EXPECT_EQ(firstFreeBusId(0x2E01, [](std::uint16_t id) { return id == 0x2E01 || id == 0x2E02; }), 0x2E03);
    EXPECT_EQ(firstFreeBusId(0xFFFF, [](std::uint16_t id) { return id == 0xFFFF; }), 0x0000);
    EXPECT_FALSE(firstFreeBusId(0x1234, [](std::uint16_t) { return true; }).has_value());
}

// 001 §Genereller Aufbau der Befehle: "die MM2 Weiche 5 ... Ziel Id 0x3005".
TEST(GenerellerAufbauDerBefehle, Mm2Weiche5HasZielId0x3005) {
    EXPECT_EQ(legacyId(LegacyKind::Mm2Decoder, 5), std::optional<std::uint16_t>(0x3005));
    const auto back = legacyAddressOf(0x3005);
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(back->range->kind, LegacyKind::Mm2Decoder);
    EXPECT_EQ(back->number, 5u);
}

// 001 §A) Legacy: MM locos 0x0000-0x00FF, MM2 decoders 0x3000-0x33FF; numbers beyond a range are refused.
TEST(ALegacyDevices, NumbersOutsideTheRangeAreRefused) {
    EXPECT_FALSE(legacyId(LegacyKind::Mm2Decoder, 0).has_value());
    EXPECT_FALSE(legacyId(LegacyKind::Mm2Decoder, 1024).has_value());
    EXPECT_EQ(legacyId(LegacyKind::Mm2Decoder, 1023), std::optional<std::uint16_t>(0x33FF));
    EXPECT_EQ(legacyId(LegacyKind::MmLoco, 72), std::optional<std::uint16_t>(0x0048));
    EXPECT_FALSE(legacyRange(LegacyKind::MmLoco).assumed);
    EXPECT_TRUE(legacyRange(LegacyKind::DccAccessory).assumed);
}

// Notes A4.2 (Derived): each vector decodes to its message and the message encodes to the vector.
TEST(Derived, A42VectorsDecodeToTheirMessages) {
    for (const Vector& v : Derived) {
        const can::CanFrame f = frame(v.frame);
        EXPECT_TRUE(isOrc(f)) << v.name;
        EXPECT_EQ(decode(f), v.message) << v.name;
    }
}

TEST(Derived, A42MessagesEncodeToTheVectors) {
    for (const Vector& v : Derived)
        EXPECT_EQ(can::formatDocument(encode(v.message)), v.frame) << v.name;
}

// Notes A4.2 (Derived): with the priority left to the codec (0), the notes' A1.4 priorities come out.
TEST(Derived, DefaultPrioritiesFollowNotesA14) {
    EXPECT_EQ(can::formatDocument(encode(AllOff{{0, 0, 0}, Target::all()})), "09000000 1 00");
    EXPECT_EQ(can::formatDocument(encode(DecoderSwitch{{0, 0, 0}, false, 0x3005, 1})),
              "11100000 4 03 30 05 01");
    EXPECT_EQ(can::formatDocument(encode(Ping{{0, 0, 0}, 0x3A2E2E01})), "19200000 5 00 3A 2E 2E 01");
}

// Notes A1.3: under L2 every ORC group reads as a CS2 command >= 0x80 (ID24..17), which Märklin nodes ignore.
TEST(Derived, EveryGroupReadsAsCs2CommandAbove0x80) {
    for (const Vector& v : Derived) {
        const can::CanFrame f = frame(v.frame);
        EXPECT_GE((f.id >> 17) & 0xFF, 0x80u) << v.name;
        EXPECT_EQ(f.id >> 27 != 0, true) << v.name;
    }
}

// 001 §Grundsätzlicher ID Aufbau, read as layout L2 (notes A1.3): the fields land where the table says.
TEST(GrundsaetzlicherIdAufbau, LayoutL2PutsEachFieldOnItsCs2Counterpart) {
    const Header h{prio::Management, 2, group::Management, true, 0x2E01};
    EXPECT_EQ(makeId(h), 0x1D212E01u);
    EXPECT_EQ(readId(0x1D212E01), h);
    EXPECT_FALSE(isOrcId(0x01FE0000)) << "priority 00 with ID24 set is kept for RO modules";
    EXPECT_FALSE(isOrcId(0x00004711)) << "a CS2 identifier";
}
