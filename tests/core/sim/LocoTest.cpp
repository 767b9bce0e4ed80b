// Chapter 3.4-3.8: speed, direction, functions and CV programming of the simulated decoders.

#include "SimTestSupport.h"

namespace stellwerk::sim::test {
namespace {

using Frames = std::vector<CanFrame>;

TEST(LocoCommands, SpeedExamplesAreConfirmedAndStored) {
    StationProbe probe;
    for (const char* line : {"00084711 6 00 00 08 03 03 20", "00084711 6 00 00 40 01 03 20",
                             "00084711 6 00 00 C0 03 01 20", "00084711 6 00 00 C0 03 00 A0"})
        EXPECT_EQ(probe.send(line), Frames{probe.answer(line)});
    EXPECT_EQ(probe.station.loco(0xC003)->speed, 0x00A0);
    EXPECT_EQ(probe.station.loco(0x0803)->speed, 0x0320);
}

TEST(LocoCommands, SpeedQueryOfAKnownLocoAndOfAnUnknownOne) {
    StationProbe probe;
    probe.send("00084711 6 00 00 C0 03 01 20");
    EXPECT_EQ(probe.send("00084711 4 00 00 C0 03"), Frames{probe.answer("00084711 6 00 00 C0 03 01 20")});
    EXPECT_EQ(probe.send("00084711 4 00 00 C0 63"), Frames{probe.answer("00084711 4 00 00 C0 63")});
}

TEST(LocoCommands, DirectionChangeResetsTheSpeed) {
    StationProbe probe;
    probe.send("00084711 6 00 00 C0 03 01 20");
    EXPECT_EQ(probe.send("000A4711 5 00 00 C0 03 02"), Frames{probe.answer("000A4711 5 00 00 C0 03 02")});
    EXPECT_EQ(probe.station.loco(0xC003)->speed, 0);
    EXPECT_EQ(probe.station.loco(0xC003)->direction, 2);
    EXPECT_EQ(probe.send("000A4711 4 00 00 C0 03"), Frames{probe.answer("000A4711 5 00 00 C0 03 02")});
}

TEST(LocoCommands, SameDirectionKeepsTheSpeedAndToggleTurns) {
    StationProbe probe;
    probe.send("00084711 6 00 00 C0 03 01 20");
    probe.send("000A4711 5 00 00 C0 03 01");
    EXPECT_EQ(probe.station.loco(0xC003)->speed, 0x0120);
    probe.send("000A4711 5 00 00 C0 03 03");
    EXPECT_EQ(probe.station.loco(0xC003)->direction, 2);
    EXPECT_EQ(probe.station.loco(0xC003)->speed, 0);
}

TEST(LocoCommands, DirectionQueryIsAnsweredEvenForAnUnknownLoco) {
    StationProbe probe;
    EXPECT_EQ(probe.send("000A4711 4 00 00 C0 64"), Frames{probe.answer("000A4711 5 00 00 C0 64 00")});
}

TEST(LocoCommands, FunctionsF0ToF31AreSetAndQueried) {
    StationProbe probe;
    EXPECT_EQ(probe.send("000C4711 6 00 00 C0 03 1F 01"),
              Frames{probe.answer("000C4711 6 00 00 C0 03 1F 01")});
    EXPECT_EQ(probe.send("000C4711 6 00 00 C0 03 00 1F"),
              Frames{probe.answer("000C4711 6 00 00 C0 03 00 1F")});
    EXPECT_EQ(probe.station.loco(0xC003)->functions[31], 1);
    // The station keeps only on/off, not a dim value (3.6).
    EXPECT_EQ(probe.send("000C4711 5 00 00 C0 03 00"), Frames{probe.answer("000C4711 6 00 00 C0 03 00 01")});
    EXPECT_EQ(probe.send("000C4711 5 00 00 C0 03 1E"), Frames{probe.answer("000C4711 6 00 00 C0 03 1E 00")});
    EXPECT_TRUE(probe.send("000C4711 6 00 00 C0 03 20 01").empty()) << "there is no F32";
}

TEST(DecoderProgramming, NewDecoderReadsItsAddressFromCv1) {
    StationProbe probe;
    EXPECT_EQ(probe.send("000E4711 7 00 00 C0 03 00 01 01"),
              Frames{probe.answer("000E4711 7 00 00 C0 03 00 01 03")});
    // vmax of lokomotive.cs2 is the decoder's CV5.
    EXPECT_EQ(probe.send("000E4711 7 00 00 C0 03 00 05 01"),
              Frames{probe.answer("000E4711 7 00 00 C0 03 00 05 C8")});
}

TEST(DecoderProgramming, WriteThenReadGivesTheWrittenValue) {
    StationProbe probe;
    EXPECT_EQ(probe.send("00104711 8 00 00 C0 03 00 03 2A 00"),
              Frames{probe.answer("00104711 8 00 00 C0 03 00 03 2A C0")});
    EXPECT_EQ(probe.send("000E4711 7 00 00 C0 03 00 03 01"),
              Frames{probe.answer("000E4711 7 00 00 C0 03 00 03 2A")});
}

TEST(DecoderProgramming, ReadingSeveralDccCvsAnswersOneFramePerCv) {
    StationProbe probe;
    const Frames answers = probe.send("000E4711 7 00 00 C0 03 00 01 03");
    ASSERT_EQ(answers.size(), 3u);
    EXPECT_EQ(answers[2], probe.answer("000E4711 7 00 00 C0 03 00 03 0A"));
}

TEST(DecoderProgramming, MfxReadCountsTheIndex) {
    StationProbe probe;
    probe.send("00104711 8 00 00 40 05 04 04 11 00"); // CV 4, index 1
    const Frames answers = probe.send("000E4711 7 00 00 40 05 00 04 02");
    ASSERT_EQ(answers.size(), 2u);
    EXPECT_EQ(answers[1], probe.answer("000E4711 7 00 00 40 05 04 04 11"));
}

TEST(DecoderProgramming, Mm2CannotBeReadButIsWrittenWithoutVerify) {
    StationProbe probe;
    EXPECT_EQ(probe.send("000E4711 7 00 00 00 48 00 01 01"),
              Frames{probe.answer("000E4711 6 00 00 00 48 00 01")});
    EXPECT_EQ(probe.send("00104711 8 00 00 00 48 00 01 10 00"),
              Frames{probe.answer("00104711 8 00 00 00 48 00 01 10 80")});
}

TEST(DecoderProgramming, UnboundMfxSidHasNoDecoder) {
    StationProbe probe;
    EXPECT_EQ(probe.send("000E4711 7 00 00 40 09 00 01 01"),
              Frames{probe.answer("000E4711 6 00 00 40 09 00 01")});
    EXPECT_EQ(probe.send("00104711 8 00 00 40 09 00 01 10 00"),
              Frames{probe.answer("00104711 8 00 00 40 09 00 01 10 00")});
}

TEST(LocoCommands, LayoutLocomotivesStartInTheCycle) {
    StationProbe probe;
    ASSERT_NE(probe.station.loco(0x4005), nullptr);
    EXPECT_TRUE(probe.station.loco(0x4005)->inCycle);
    EXPECT_EQ(probe.send("00084711 4 00 00 40 05"), Frames{probe.answer("00084711 6 00 00 40 05 00 00")});
}

} // namespace
} // namespace stellwerk::sim::test
