// Chapter 2, system commands: each documented example, answered with the response bit.

#include "SimTestSupport.h"
#include "cs2/Hash.h"

namespace stellwerk::sim::test {
namespace {

using Power = SimulatedStation::Power;
using Frames = std::vector<CanFrame>;

TEST(SystemCommands, StopToEverybodyIsConfirmedAndSwitchesTheTrackOff) {
    StationProbe probe;
    probe.send("00004711 5 00 00 00 00 01");
    EXPECT_EQ(probe.send("00004711 5 00 00 00 00 00"), Frames{probe.answer("00004711 5 00 00 00 00 00")});
    EXPECT_EQ(probe.station.power(), Power::Stopped);
}

TEST(SystemCommands, StopGoHaltAddressedToThisStation) {
    StationProbe probe;
    EXPECT_EQ(probe.send("00004711 5 43 53 32 08 01"), Frames{probe.answer("00004711 5 43 53 32 08 01")});
    EXPECT_EQ(probe.station.power(), Power::Running);
    EXPECT_EQ(probe.send("00004711 5 43 53 32 08 02"), Frames{probe.answer("00004711 5 43 53 32 08 02")});
    EXPECT_EQ(probe.station.power(), Power::Halted);
    EXPECT_EQ(probe.send("00004711 5 43 53 32 08 00"), Frames{probe.answer("00004711 5 43 53 32 08 00")});
    EXPECT_EQ(probe.station.power(), Power::Stopped);
}

TEST(SystemCommands, CommandsToAnotherStationGetNoAnswer) {
    StationProbe probe;
    EXPECT_TRUE(probe.send("00004711 5 43 53 32 09 01").empty());
    EXPECT_EQ(probe.station.power(), Power::Stopped);
    EXPECT_TRUE(probe.send("00004711 7 43 53 32 09 09 00 02").empty());
}

TEST(SystemCommands, HaltBringsEveryLocoToSpeedZero) {
    StationProbe probe;
    probe.send("00084711 6 00 00 C0 03 01 20");
    probe.send("00004711 5 00 00 00 00 02");
    EXPECT_EQ(probe.station.loco(0xC003)->speed, 0);
    EXPECT_EQ(probe.station.power(), Power::Halted);
}

TEST(SystemCommands, LocoEmergencyStopExamples) {
    StationProbe probe;
    probe.send("00084711 6 00 00 C0 03 01 20");
    EXPECT_EQ(probe.send("00004711 5 00 00 C0 03 03"), Frames{probe.answer("00004711 5 00 00 C0 03 03")});
    EXPECT_EQ(probe.station.loco(0xC003)->speed, 0);
    EXPECT_EQ(probe.send("00004711 5 00 00 00 48 03"), Frames{probe.answer("00004711 5 00 00 00 48 03")});
    EXPECT_EQ(probe.send("00004711 5 00 00 40 05 03"), Frames{probe.answer("00004711 5 00 00 40 05 03")});
}

TEST(SystemCommands, LocoCycleEndForgetsTheLocoAndStationUidClearsTheTable) {
    StationProbe probe;
    probe.send("00084711 6 00 00 C0 03 01 20");
    EXPECT_EQ(probe.send("00004711 5 00 00 C0 03 04"), Frames{probe.answer("00004711 5 00 00 C0 03 04")});
    // A speed query of a loco outside the cycle is answered without a speed (3.4).
    EXPECT_EQ(probe.send("00084711 4 00 00 C0 03"), Frames{probe.answer("00084711 4 00 00 C0 03")});
    EXPECT_EQ(probe.send("00004711 5 43 53 32 08 04"), Frames{probe.answer("00004711 5 43 53 32 08 04")});
    EXPECT_FALSE(probe.station.loco(0x4005)->inCycle);
}

TEST(SystemCommands, LocoProtocolExampleAndNoAnswerForMfx) {
    StationProbe probe;
    EXPECT_EQ(probe.send("00004711 6 00 00 C0 03 05 02"),
              Frames{probe.answer("00004711 6 00 00 C0 03 05 02")});
    EXPECT_EQ(probe.station.loco(0xC003)->trackProtocol, 2);
    EXPECT_TRUE(probe.send("00004711 6 00 00 40 05 05 02").empty());
}

TEST(SystemCommands, SwitchTimeExample) {
    StationProbe probe;
    EXPECT_EQ(probe.send("00004711 7 00 00 00 00 06 00 0A"),
              Frames{probe.answer("00004711 7 00 00 00 00 06 00 0A")});
}

TEST(SystemCommands, TrackProtocolsAndMfxRegistrationCounterExample) {
    StationProbe probe;
    EXPECT_EQ(probe.send("00004711 6 43 53 32 08 08 05"),
              Frames{probe.answer("00004711 6 43 53 32 08 08 05")});
    EXPECT_EQ(probe.send("00004711 7 43 53 32 08 09 00 02"),
              Frames{probe.answer("00004711 7 43 53 32 08 09 00 02")});
    // mfx is blocked now: a discovery finds nothing (DLC 0 answer).
    EXPECT_EQ(probe.send("00024711 1 20"), Frames{probe.answer("00024711 0")});
}

TEST(SystemCommands, FastReadIsAlwaysConfirmed) {
    StationProbe probe;
    EXPECT_EQ(probe.send("00004711 7 43 53 32 08 07 00 05"),
              Frames{probe.answer("00004711 7 43 53 32 08 07 00 05")});
}

TEST(SystemCommands, DeviceIdQueryAndAssignment) {
    StationProbe probe;
    EXPECT_EQ(probe.send("00004711 7 43 53 32 08 0C 00 2A"),
              Frames{probe.answer("00004711 7 43 53 32 08 0C 00 2A")});
    EXPECT_EQ(probe.send("00004711 5 43 53 32 08 0C"),
              Frames{probe.answer("00004711 7 43 53 32 08 0C 00 2A")});
}

TEST(SystemCommands, ResetStopsTheTrackAndEmptiesTheCycle) {
    StationProbe probe;
    probe.send("00004711 5 00 00 00 00 01");
    EXPECT_EQ(probe.send("00004711 6 43 53 32 08 80 FF"),
              Frames{probe.answer("00004711 6 43 53 32 08 80 FF")});
    EXPECT_EQ(probe.station.power(), Power::Stopped);
    EXPECT_FALSE(probe.station.loco(0xC003)->inCycle);
}

TEST(SystemCommands, AnotherSenderWithOurHashMakesTheStationChooseANewOne) {
    StationProbe probe;
    const std::uint16_t before = probe.station.hash();
    EXPECT_EQ(before, cs2::hashFromUid(DocumentUid));
    CanFrame clash = frame("00004711 5 00 00 00 00 01");
    clash.id = cs2::makeId(0, 0x00, false, before);
    const Frames answer = probe.send(clash);
    EXPECT_NE(probe.station.hash(), before);
    ASSERT_EQ(answer.size(), 1u);
    EXPECT_EQ(cs2::hash(answer[0]), probe.station.hash());
}

TEST(SystemCommands, ResponsesOfOtherDevicesAreNotCommands) {
    StationProbe probe;
    EXPECT_TRUE(probe.send("00014711 5 00 00 00 00 01").empty());
    EXPECT_EQ(probe.station.power(), Power::Stopped);
}

} // namespace
} // namespace stellwerk::sim::test
