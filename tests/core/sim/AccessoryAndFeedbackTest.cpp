// Chapter 4 (accessories) and chapter 5 (S88 feedback).

#include "SimTestSupport.h"

namespace stellwerk::sim::test {
namespace {

using Frames = std::vector<CanFrame>;

TEST(AccessoryCommands, SwitchIsConfirmedAndThePositionKept) {
    StationProbe probe;
    EXPECT_EQ(probe.station.accessoryPosition(0x3000), 1) << "from magnetartikel.cs2";
    EXPECT_EQ(probe.send("00164711 6 00 00 30 00 00 01"),
              Frames{probe.answer("00164711 6 00 00 30 00 00 01")});
    // The switch-off frame is confirmed too and leaves the position.
    EXPECT_EQ(probe.send("00164711 6 00 00 30 00 00 00"),
              Frames{probe.answer("00164711 6 00 00 30 00 00 00")});
    EXPECT_EQ(probe.station.accessoryPosition(0x3000), 0);
}

TEST(AccessoryCommands, SwitchWithTimeAndDccPositions) {
    StationProbe probe;
    EXPECT_EQ(probe.send("00164711 8 00 00 38 04 01 01 00 0A"),
              Frames{probe.answer("00164711 8 00 00 38 04 01 01 00 0A")});
    EXPECT_EQ(probe.station.accessoryPosition(0x3804), 1);
    EXPECT_TRUE(probe.send("00164711 6 00 00 38 04 02 01").empty()) << "DCC knows positions 0 and 1 only";
    EXPECT_TRUE(probe.send("00164711 6 00 00 C0 03 01 01").empty()) << "a loco address is no accessory";
}

TEST(Feedback, SetContactEmitsTheEventAndTheQueryAnswersIt) {
    StationProbe probe;
    probe.station.setContact(0, 12, true);
    ASSERT_EQ(probe.batches.size(), 1u);
    ASSERT_EQ(probe.batches[0].size(), 1u);
    const CanFrame event = probe.batches[0][0];
    EXPECT_EQ(event.id, cs2::makeId(0, 0x11, true, probe.station.hash()));
    EXPECT_EQ(event.dlc, 8);
    const auto reported = std::get<cs2::S88Event>(probe.decoded(event).body);
    EXPECT_EQ(reported.contact, 12);
    EXPECT_EQ(reported.change->oldState, 0);
    EXPECT_EQ(reported.change->newState, 1);

    const Frames answers = probe.send("00224711 4 00 00 00 0C");
    ASSERT_EQ(answers.size(), 1u);
    const auto body = std::get<cs2::S88Event>(probe.decoded(answers[0]).body);
    EXPECT_EQ(body.contact, 12);
    ASSERT_TRUE(body.change);
    EXPECT_EQ(body.change->oldState, 1);
    EXPECT_EQ(body.change->newState, 1);
    EXPECT_TRUE(probe.station.contact(0, 12));
}

TEST(Feedback, ReleasingReportsOldAndNewStateAndRepeatsAreSilent) {
    StationProbe probe;
    probe.station.setContact(0x0100, 1001, true);
    probe.station.setContact(0x0100, 1001, true);
    EXPECT_EQ(probe.batches.size(), 1u);
    probe.station.setContact(0x0100, 1001, false);
    ASSERT_EQ(probe.batches.size(), 2u);
    const auto body = std::get<cs2::S88Event>(probe.decoded(probe.batches[1][0]).body);
    EXPECT_EQ(body.device, 0x0100);
    EXPECT_EQ(body.contact, 1001);
    EXPECT_EQ(body.change->oldState, 1);
    EXPECT_EQ(body.change->newState, 0);
}

TEST(Feedback, UnknownContactQueryAnswersFree) {
    StationProbe probe;
    EXPECT_EQ(probe.send("00224711 4 00 00 00 05"),
              Frames{probe.answer("00224711 8 00 00 00 05 00 00 00 00")});
}

TEST(Feedback, S88PollingAnswersOneFramePerModule) {
    StationProbe probe;
    probe.station.setContact(0, 1, true);
    probe.station.setContact(0, 18, true);
    EXPECT_EQ(probe.send("00204711 5 43 53 32 08 02"),
              (Frames{probe.answer("00204711 7 43 53 32 08 01 80 00"),
                      probe.answer("00204711 7 43 53 32 08 02 40 00")}));
    EXPECT_TRUE(probe.send("00204711 5 43 53 32 09 01").empty());
}

} // namespace
} // namespace stellwerk::sim::test
