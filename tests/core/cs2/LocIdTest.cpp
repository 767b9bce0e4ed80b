#include "cs2/LocId.h"

#include <gtest/gtest.h>

using namespace stellwerk::cs2;

struct RangeCase {
    std::uint32_t first;
    std::uint32_t last;
    LocIdRange range;
    Protocol protocol;
};

class LocIdRanges : public testing::TestWithParam<RangeCase> {};

// Document 1.3.1.2: every row of the address table, both ends.
TEST_P(LocIdRanges, BothEndsOfEachRowBelongToIt) {
    const auto c = GetParam();
    for (auto value : {c.first, c.last}) {
        const LocId id(value);
        EXPECT_EQ(id.range(), c.range) << std::hex << value;
        EXPECT_EQ(id.protocol(), c.protocol) << std::hex << value;
        EXPECT_EQ(id.offset(), value - c.first) << std::hex << value;
    }
}

INSTANTIATE_TEST_SUITE_P(
    Document_1_3_1_2, LocIdRanges,
    testing::Values(RangeCase{0x0000, 0x03FF, LocIdRange::Mm2, Protocol::Mm2},
                    RangeCase{0x0400, 0x07FF, LocIdRange::Reserved, Protocol::Other},
                    RangeCase{0x0800, 0x0BFF, LocIdRange::Sx1, Protocol::Sx1},
                    RangeCase{0x0C00, 0x0FFF, LocIdRange::Reserved, Protocol::Other},
                    RangeCase{0x1000, 0x13FF, LocIdRange::Mm2FunctionDecoder, Protocol::Other},
                    RangeCase{0x1400, 0x17FF, LocIdRange::Reserved, Protocol::Other},
                    RangeCase{0x1800, 0x1BFF, LocIdRange::Private, Protocol::Other},
                    RangeCase{0x1C00, 0x1FFF, LocIdRange::Company, Protocol::Other},
                    RangeCase{0x2000, 0x23FF, LocIdRange::Mm2Loco20kHz, Protocol::Other},
                    RangeCase{0x2400, 0x27FF, LocIdRange::Reserved, Protocol::Other},
                    RangeCase{0x2800, 0x2BFF, LocIdRange::Sx1Accessory, Protocol::Sx1Accessory},
                    RangeCase{0x2C00, 0x2FFF, LocIdRange::Traction, Protocol::Other},
                    RangeCase{0x3000, 0x33FF, LocIdRange::Mm2Accessory, Protocol::Mm2Accessory},
                    RangeCase{0x3400, 0x37FF, LocIdRange::Reserved, Protocol::Other},
                    RangeCase{0x3800, 0x3FFF, LocIdRange::DccAccessory, Protocol::DccAccessory},
                    RangeCase{0x4000, 0x7FFF, LocIdRange::Mfx, Protocol::Mfx},
                    RangeCase{0x8000, 0xBFFF, LocIdRange::Sx2, Protocol::Sx2},
                    RangeCase{0xC000, 0xFFFF, LocIdRange::Dcc, Protocol::Dcc},
                    RangeCase{0x10000, 0xFFFFFFFF, LocIdRange::DeviceUid, Protocol::Other}));

TEST(LocId, LocoAddressesCountFromTheRangeBase) {
    EXPECT_EQ(LocId::fromAddress(Protocol::Mm2, 72)->value(), 0x0048u);
    EXPECT_EQ(LocId::fromAddress(Protocol::Dcc, 3)->value(), 0xC003u);
    EXPECT_EQ(LocId::fromAddress(Protocol::Mfx, 5)->value(), 0x4005u);
    EXPECT_EQ(LocId::fromAddress(Protocol::Sx1, 3)->value(), 0x0803u);
    EXPECT_EQ(LocId::fromAddress(Protocol::Sx2, 100)->value(), 0x8064u);
    EXPECT_EQ(LocId(0xC003).address(), 3u);
}

// Field notes: accessory numbers users see are 1-based; the document's example counts from 0.
TEST(LocId, AccessoryAddressesAreOneBasedKeyboardNumbers) {
    EXPECT_EQ(LocId::fromAddress(Protocol::Mm2Accessory, 1)->value(), 0x3000u);
    EXPECT_EQ(LocId::fromAddress(Protocol::DccAccessory, 1)->value(), 0x3800u);
    EXPECT_EQ(LocId::fromAddress(Protocol::DccAccessory, 2048)->value(), 0x3FFFu);
    EXPECT_EQ(LocId::fromAddress(Protocol::Sx1Accessory, 1)->value(), 0x2800u);
    const LocId documentExample(0x3003); // "MM2 Zubehör mit Adresse 3"
    EXPECT_EQ(documentExample.offset(), 3u);
    EXPECT_EQ(documentExample.address(), 4u);
    EXPECT_TRUE(documentExample.isAccessory());
}

TEST(LocId, RejectsAddressesOutsideTheProtocolsRange) {
    EXPECT_FALSE(LocId::fromAddress(Protocol::Mm2Accessory, 0).has_value());
    EXPECT_FALSE(LocId::fromAddress(Protocol::Mm2Accessory, 1025).has_value());
    EXPECT_FALSE(LocId::fromAddress(Protocol::Dcc, 0x4000).has_value());
    EXPECT_FALSE(LocId::fromAddress(Protocol::Other, 1).has_value());
}

TEST(LocId, ProtocolNamesRoundTrip) {
    for (auto p : {Protocol::Mm2, Protocol::Sx1, Protocol::Mfx, Protocol::Sx2, Protocol::Dcc,
                   Protocol::Mm2Accessory, Protocol::DccAccessory, Protocol::Sx1Accessory, Protocol::Other})
        EXPECT_EQ(protocolFromName(protocolName(p)), p);
    EXPECT_EQ(protocolName(Protocol::DccAccessory), "dcc-accessory");
    EXPECT_FALSE(protocolFromName("dcc2").has_value());
}
