// The protocol-neutral description of a frame that the bus monitor, the frame decoder and
// `stellwerk-cli decode` show.

#include "busreading/FrameDescription.h"

#include <algorithm>
#include <gtest/gtest.h>

namespace stellwerk::busreading::test {
namespace {

using can::CanFrame;

const BusProfile CentralStationBus = BusProfile::centralStation();

// Document 3.3: loco speed 288 for the DCC loco 3 (Loc-ID 0xC003) from hash 0x4711.
CanFrame locoSpeed() {
    const std::uint8_t data[] = {0x00, 0x00, 0xC0, 0x03, 0x01, 0x20};
    return CanFrame::extendedFrame(0x00084711, data);
}

TEST(FrameDescription, ACs2FrameIsDescribedByTheCs2Codec) {
    const FrameDescription description(locoSpeed(), CentralStationBus);
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
    const FrameDescription description(CanFrame::extendedFrame(0x00084711, data), CentralStationBus);
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
    EXPECT_TRUE(FrameDescription(CanFrame::extendedFrame(0x00094711, data), CentralStationBus).isResponse());
}

TEST(FrameDescription, AForeignFrameIsShownNotDecoded) {
    const std::uint8_t data[] = {0x01, 0x02};
    const FrameDescription description(CanFrame::standard(0x123, data), CentralStationBus);
    EXPECT_EQ(description.protocol(), Protocol::Foreign);
    EXPECT_EQ(description.name(), "foreign");
    EXPECT_FALSE(description.decoded());
    EXPECT_EQ(description.frameText(), "123 2 01 02");
    EXPECT_EQ(description.detailText(), "11-bit frame (no protocol of a CS2/M-CAN bus)");
    EXPECT_EQ(description.text(), "123 2 01 02  foreign 11-bit frame (no protocol of a CS2/M-CAN bus)");
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
    const std::vector<std::string_view> names = messageNames(CentralStationBus);
    EXPECT_NE(std::find(names.begin(), names.end(), "loco.speed"), names.end());
    EXPECT_NE(std::find(names.begin(), names.end(), "system.go"), names.end());
    const auto poll = std::find(names.begin(), names.end(), "mcan.poll");
    EXPECT_NE(poll, names.end());
    EXPECT_GT(poll - names.begin(), std::find(names.begin(), names.end(), "system.go") - names.begin())
        << "the CS2's names come first";
    const std::vector<std::string_view> cs2Only = messageNames(BusProfile{Protocol::Cs2});
    EXPECT_EQ(std::find(cs2Only.begin(), cs2Only.end(), "mcan.poll"), cs2Only.end());
    EXPECT_TRUE(messageNames(BusProfile{}).empty());
}

// M-CAN notes B§4.2, trace #82: the MS1 (node 43) polls its master (node 42) on the poll handle.
TEST(FrameDescription, AnMcanFrameIsDescribedByTheMcanCodec) {
    const std::uint8_t data[] = {0x00, 0x00, 0x00, 0x2A};
    const FrameDescription description(CanFrame::extendedFrame(0x0C0007AB, data), CentralStationBus);
    EXPECT_EQ(description.protocol(), Protocol::Mcan);
    EXPECT_EQ(description.protocolName(), "mcan");
    EXPECT_EQ(description.name(), "mcan.poll");
    EXPECT_TRUE(description.decoded());
    EXPECT_FALSE(description.isResponse());
    EXPECT_EQ(description.frameText(), "0C0007AB 4 00 00 00 2A");
    EXPECT_EQ(description.number("node"), 43u);
    EXPECT_EQ(description.number("masterNode"), 42u);
    EXPECT_EQ(description.detailText(), "from=slave node=43 handle=0x0001 prio=3 masterNode=42");
    EXPECT_EQ(description.text(), "0C0007AB 4 00 00 00 2A  mcan.poll  " + description.detailText());
    EXPECT_EQ(description.json(),
              "{\"protocol\":\"mcan\",\"id\":\"0C0007AB\",\"dlc\":4,\"data\":\"0000002A\","
              "\"name\":\"mcan.poll\",\"fields\":{\"from\":\"slave\",\"node\":43,"
              "\"handle\":\"0x0001\",\"prio\":3,\"masterNode\":42}}");
    ASSERT_TRUE(description.handheld());
    EXPECT_EQ(description.handheld()->node, 43);
    EXPECT_EQ(description.handheld()->name, "");
}

TEST(FrameDescription, AnMcanFrameOfNoDocumentedFormIsUnknownWithItsReason) {
    const std::uint8_t data[] = {0x00, 0x00};
    const FrameDescription description(CanFrame::extendedFrame(0x10000281, data),
                                       CentralStationBus); // trace #2
    EXPECT_EQ(description.protocol(), Protocol::Mcan);
    EXPECT_EQ(description.name(), "mcan.unknown");
    EXPECT_FALSE(description.decoded());
    EXPECT_NE(description.detailText().find("why="), std::string::npos) << description.detailText();
}

// The master's node (42) and the slave's (43) belong to one handheld; login frames before the grant,
// the bus-busy frame and CS2 frames to none.
TEST(FrameDescription, AnMcanFrameNamesTheSlaveNodeOfItsPair) {
    const std::uint8_t answer[] = {0x40, 0x2B, 0x00, 0x00, 0x00, 0x08, 0x00, 0x01};
    const FrameDescription fromMaster(CanFrame::extendedFrame(0x18000A2A, answer),
                                      CentralStationBus); // trace #18
    ASSERT_TRUE(fromMaster.handheld());
    EXPECT_EQ(fromMaster.handheld()->node, 43);
    const std::uint8_t grant[] = {0x00, 0x02, 0x04, 0xB3, 0x00, 0x02, 0xAB, 0x00};
    const FrameDescription granted(CanFrame::extendedFrame(0x1C03B0FE, grant),
                                   CentralStationBus); // trace #16
    ASSERT_TRUE(granted.handheld());
    EXPECT_EQ(granted.handheld()->node, 43);
    EXPECT_FALSE(FrameDescription(CanFrame::extendedFrame(0x1C00007E, {}), CentralStationBus).handheld());
    const std::uint8_t zeros[8] = {};
    EXPECT_FALSE(FrameDescription(CanFrame::extendedFrame(0x380, zeros), CentralStationBus).handheld());
    EXPECT_FALSE(FrameDescription(locoSpeed(), CentralStationBus).handheld());
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
} // namespace stellwerk::busreading::test
