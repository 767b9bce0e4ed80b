// The protocol-neutral description of a frame that the bus monitor, the frame decoder and
// `stellwerk-cli decode` show.

#include "bus/FrameDescription.h"

#include <algorithm>
#include <gtest/gtest.h>

namespace stellwerk::bus::test {
namespace {

using can::CanFrame;

const BusProfile Station = BusProfile::centralStation();

// Document 3.3: loco speed 288 for the DCC loco 3 (Loc-ID 0xC003) from hash 0x4711.
CanFrame locoSpeed() {
    const std::uint8_t data[] = {0x00, 0x00, 0xC0, 0x03, 0x01, 0x20};
    return CanFrame::extendedFrame(0x00084711, data);
}

TEST(FrameDescription, ACs2FrameIsDescribedByTheCs2Codec) {
    const FrameDescription description(locoSpeed(), Station);
    EXPECT_EQ(description.protocol(), Protocol::Cs2);
    EXPECT_EQ(description.protocolName(), "cs2");
    EXPECT_EQ(description.name(), "loco.speed");
    EXPECT_TRUE(description.decoded());
    EXPECT_FALSE(description.isResponse());
    EXPECT_EQ(description.frameText(), "00084711 6 00 00 C0 03 01 20");
    EXPECT_EQ(description.number("locId"), 0xC003u);
    EXPECT_EQ(description.number("speed"), 288u);
    EXPECT_EQ(description.number("nothing"), std::nullopt);
    EXPECT_NE(description.detailText().find("speed=288"), std::string::npos) << description.detailText();
    EXPECT_EQ(description.text().rfind(description.frameText() + "  loco.speed", 0), 0u)
        << description.text();
    EXPECT_EQ(description.json().rfind("{\"protocol\":\"cs2\",\"id\":\"00084711\",", 0), 0u)
        << description.json();
    EXPECT_NE(description.json().find("\"name\":\"loco.speed\""), std::string::npos);
}

TEST(FrameDescription, AFrameThatDoesNotDecodeKeepsItsIntendedNameAndSaysWhy) {
    const std::uint8_t data[] = {0x00, 0x00, 0xC0, 0x03, 0x01};
    const FrameDescription description(CanFrame::extendedFrame(0x00084711, data), Station);
    EXPECT_EQ(description.protocol(), Protocol::Cs2);
    EXPECT_EQ(description.name(), "loco.speed");
    EXPECT_FALSE(description.decoded());
    EXPECT_EQ(description.number("locId"), std::nullopt);
    EXPECT_NE(description.detailText().find("unexpected length 5"), std::string::npos)
        << description.detailText();
    EXPECT_NE(description.text().find("ERROR"), std::string::npos) << description.text();
}

TEST(FrameDescription, AResponseIsMarked) {
    const std::uint8_t data[] = {0x00, 0x00, 0xC0, 0x03, 0x01, 0x20};
    EXPECT_TRUE(FrameDescription(CanFrame::extendedFrame(0x00094711, data), Station).isResponse());
}

TEST(FrameDescription, AForeignFrameIsShownNotDecoded) {
    const std::uint8_t data[] = {0x01, 0x02};
    const FrameDescription description(CanFrame::standard(0x123, data), Station);
    EXPECT_EQ(description.protocol(), Protocol::Foreign);
    EXPECT_EQ(description.name(), "foreign");
    EXPECT_FALSE(description.decoded());
    EXPECT_EQ(description.frameText(), "123 2 01 02");
    EXPECT_EQ(description.detailText(), "11-bit frame (no protocol of a CS2 bus)");
    EXPECT_EQ(description.text(), "123 2 01 02  foreign 11-bit frame (no protocol of a CS2 bus)");
    EXPECT_EQ(description.json(),
              "{\"protocol\":\"foreign\",\"id\":\"123\",\"extended\":false,\"dlc\":2,\"data\":\"0102\"}");
}

TEST(FrameDescription, OnABusWithoutCs2EvenACs2FrameIsForeign) {
    const FrameDescription description(locoSpeed(), BusProfile{});
    EXPECT_EQ(description.protocol(), Protocol::Foreign);
    EXPECT_EQ(description.json(), "{\"protocol\":\"foreign\",\"id\":\"00084711\",\"extended\":true,\"dlc\":6,"
                                  "\"data\":\"0000C0030120\"}");
}

TEST(FrameDescription, MessageNamesComeFromTheProtocolsOfTheBus) {
    const std::vector<std::string_view> names = messageNames(Station);
    EXPECT_NE(std::find(names.begin(), names.end(), "loco.speed"), names.end());
    EXPECT_NE(std::find(names.begin(), names.end(), "system.go"), names.end());
    EXPECT_TRUE(messageNames(BusProfile{}).empty());
}

TEST(LocoReference, ReadsALocIdOrAProtocolWithAnAddress) {
    EXPECT_EQ(parseLocoReference("0x4005"), 0x4005u);
    EXPECT_EQ(parseLocoReference("16389"), 16389u);
    EXPECT_EQ(parseLocoReference("dcc 3"), 0xC003u);
    EXPECT_EQ(parseLocoReference("  DCC   3 "), 0xC003u);
    EXPECT_EQ(parseLocoReference("mm2 5"), 0x0005u);
    EXPECT_EQ(parseLocoReference("mfx 12"), 0x400Cu);
}

TEST(LocoReference, RefusesWhatIsNoLocomotive) {
    EXPECT_EQ(parseLocoReference(""), std::nullopt);
    EXPECT_EQ(parseLocoReference("dcc"), std::nullopt);
    EXPECT_EQ(parseLocoReference("dcc x"), std::nullopt);
    EXPECT_EQ(parseLocoReference("dcc 0x3"), std::nullopt);
    EXPECT_EQ(parseLocoReference("steam 3"), std::nullopt);
    EXPECT_EQ(parseLocoReference("dcc 3 4"), std::nullopt);
    EXPECT_EQ(parseLocoReference("0xZZ"), std::nullopt);
}

// On a bus that expects no protocol (a module bus before its protocol is built), the reason says so.
TEST(FrameDescription, AForeignFrameSaysWhatItsBusExpects) {
    const std::uint8_t data[] = {0, 0, 0, 0, 0};
    const CanFrame stop = CanFrame::extendedFrame(0x00004711, data);
    EXPECT_EQ(FrameDescription(stop, BusProfile{}).detailText(),
              "29-bit frame (no protocol expected on this bus)");
    EXPECT_EQ(FrameDescription(stop, BusProfile{}).name(), "foreign");
    EXPECT_EQ(FrameDescription(stop, BusProfile::centralStation()).name(), "system.stop");
}

} // namespace
} // namespace stellwerk::bus::test
