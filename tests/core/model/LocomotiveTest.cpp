// Document 3.4-3.6: speed, direction and functions, driven through the railway and shown as the station
// confirmed them; and a flood of speed answers gives one change signal.

#include "ModelBench.h"
#include "cs2/Codec.h"

namespace stellwerk::model::test {
namespace {

class LocomotiveIntents : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_TRUE(bench.start()); }

    const Locomotive& br86() const { return *bench.railway.locomotive(Br86); }

    ModelBench bench;
};

TEST_F(LocomotiveIntents, SetSpeedShowsTheSpeedTheStationConfirmed) {
    QSignalSpy changed(&bench.railway, &Railway::locomotivesChanged);
    bench.railway.setSpeed(Br86, 500);
    EXPECT_EQ(br86().speed(), 0) << "nothing changes before the station confirms";
    ASSERT_TRUE(waitFor([&] { return br86().speed() == 500; }));
    EXPECT_EQ(bench.station.loco(Br86)->speed, 500);
    ASSERT_GE(changed.count(), 1);
    EXPECT_EQ(changed.last().at(0).value<QList<quint32>>(), QList<quint32>{Br86});
}

// Issue 11: once the connection is lost nothing is "reported"; a start-up whose speed query got no answer
// leaves the speed not reported, even though load() says the railway's state is reported again.
TEST_F(LocomotiveIntents, SpeedIsNotReportedAfterALossUntilTheStationAnswersAgain) {
    bench.railway.setSpeed(Br86, 500);
    ASSERT_TRUE(waitFor([&] { return br86().speed() == 500; }));
    EXPECT_TRUE(br86().isSpeedReported());
    QSignalSpy changed(&bench.railway, &Railway::locomotivesChanged);
    bench.stationEnd.close();
    EXPECT_FALSE(bench.railway.isStateReported());
    EXPECT_FALSE(br86().isSpeedReported());
    EXPECT_EQ(br86().speed(), 500) << "the last value stays, shown as not reported";
    ASSERT_EQ(changed.count(), 1);
    EXPECT_TRUE(changed.first().at(0).value<QList<quint32>>().contains(Br86));

    bench.stationEnd.open();
    bench.deaf = true; // connected again, but the start-up's queries get no answer
    ASSERT_TRUE(bench.start());
    EXPECT_TRUE(bench.railway.isStateReported());
    EXPECT_FALSE(br86().isSpeedReported()) << "a failed re-read is not resurrected as reported";

    bench.deaf = false;
    ASSERT_TRUE(bench.start());
    EXPECT_TRUE(br86().isSpeedReported());
    EXPECT_EQ(br86().speed(), 500);
}

TEST_F(LocomotiveIntents, SpeedAboveTheSystemRangeIsSentAs1000) {
    bench.railway.setSpeed(Br86, 1023);
    ASSERT_TRUE(waitFor([&] { return br86().speed() == 1000; }));
    EXPECT_EQ(bench.station.loco(Br86)->speed, 1000);
}

// Field notes: on a direction change the station sets speed 0 but does not announce it.
TEST_F(LocomotiveIntents, DirectionChangeStopsTheLocomotive) {
    bench.railway.setSpeed(Br86, 400);
    ASSERT_TRUE(waitFor([&] { return br86().speed() == 400; }));
    bench.railway.setDirection(Br86, cs2::Direction::Backward);
    ASSERT_TRUE(waitFor([&] { return br86().direction() == cs2::Direction::Backward; }));
    EXPECT_EQ(br86().speed(), 0);
    EXPECT_EQ(bench.station.loco(Br86)->direction, 2);
    EXPECT_EQ(bench.station.loco(Br86)->speed, 0);
}

TEST_F(LocomotiveIntents, ReverseTurnsTheLocomotiveAround) {
    bench.railway.reverse(Br86);
    ASSERT_TRUE(waitFor([&] { return br86().direction() == cs2::Direction::Backward; }));
    bench.railway.reverse(Br86);
    ASSERT_TRUE(waitFor([&] { return br86().direction() == cs2::Direction::Forward; }));
}

TEST_F(LocomotiveIntents, ToggleFunctionSwitchesItOnAndOff) {
    ASSERT_FALSE(br86().functionOn(1));
    bench.railway.toggleFunction(Br86, 1);
    ASSERT_TRUE(waitFor([&] { return br86().functionOn(1); }));
    EXPECT_EQ(bench.station.loco(Br86)->functions[1], 1);
    bench.railway.toggleFunction(Br86, 1);
    ASSERT_TRUE(waitFor([&] { return !br86().functionOn(1); }));
    EXPECT_EQ(bench.station.loco(Br86)->functions[1], 0);
}

TEST_F(LocomotiveIntents, FunctionsAboveF31AreRefused) {
    QSignalSpy problems(&bench.railway, &Railway::problem);
    bench.railway.setFunction(Br86, 32, true);
    ASSERT_EQ(problems.count(), 1);
    EXPECT_TRUE(problems.first().at(0).toString().contains("F32"));
}

// Another controller (an MS2 on the same bus) drives a locomotive: the railway follows what the bus shows.
TEST_F(LocomotiveIntents, FollowsWhatAnotherControllerDoes) {
    const cs2::Message other{0, false, 0x1234, cs2::LocoSpeed{cs2::LocId(V100), 250}};
    bench.station.receive(cs2::encode(other));
    ASSERT_TRUE(waitFor([&] { return bench.railway.locomotive(V100)->speed() == 250; }));
}

TEST_F(LocomotiveIntents, AThousandSpeedAnswersInOneBatchGiveOneChangeSignal) {
    std::vector<can::CanFrame> flood;
    for (std::uint32_t address = 1; address <= 1000; ++address) {
        const cs2::LocoSpeed answer{cs2::LocId(0xC000 + address), std::uint16_t(address % 1000 + 1)};
        flood.push_back(cs2::encode(cs2::Message{0, true, 0x4711, answer}));
    }
    QSignalSpy changed(&bench.railway, &Railway::locomotivesChanged);
    bench.stationEnd.sendBatch(flood);
    ASSERT_TRUE(waitFor([&] { return changed.count() >= 1; }));
    QTest::qWait(50);
    ASSERT_EQ(changed.count(), 1);
    const auto ids = changed.first().at(0).value<QList<quint32>>();
    EXPECT_EQ(ids.size(), 1000);
    EXPECT_EQ(bench.railway.locomotive(0xC000 + 999)->speed(), 1000);
    EXPECT_EQ(bench.railway.locomotive(V100)->speed(), 4);
    EXPECT_EQ(bench.railway.locomotive(V100)->name(), "V 100") << "a known locomotive keeps its name";
    EXPECT_EQ(bench.railway.locomotive(0xC000 + 999)->displayName(), "DCC 999");
}

TEST(Locomotive, TakesNameFunctionsAndSavedStateFromTheFile) {
    cs2config::Locomotive record;
    record.uid = 0x4006;
    record.name = "BR 86";
    record.velocity = 300;
    record.direction = cs2config::TravelDirection::Backward;
    record.functions.push_back({2, 10, 0, 1, {}});
    record.functions.push_back({0, 1, 0, 0, {}});
    const Locomotive loco = Locomotive::fromFile(record);
    EXPECT_EQ(loco.speed(), 300);
    EXPECT_EQ(loco.direction(), cs2::Direction::Backward);
    ASSERT_EQ(loco.functions().size(), 2u);
    EXPECT_EQ(loco.functions()[0].number, 0) << "sorted by number";
    EXPECT_TRUE(loco.functionOn(2));
}

TEST(Locomotive, ADirectionAnswerThatRepeatsTheDirectionKeepsTheSpeed) {
    Locomotive loco{cs2::LocId(Br86)};
    loco.confirmDirection(cs2::Direction::Forward);
    loco.confirmSpeed(300);
    EXPECT_FALSE(loco.confirmDirection(cs2::Direction::Forward)) << "a query's answer";
    EXPECT_EQ(loco.speed(), 300);
    EXPECT_TRUE(loco.confirmDirection(cs2::Direction::Backward));
    EXPECT_EQ(loco.speed(), 0);
}

} // namespace
} // namespace stellwerk::model::test
