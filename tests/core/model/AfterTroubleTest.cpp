// Issue 32: a station that stalls (stops reading without closing) and then reads everything at once
// carries out the copies of commands the session had already given up on. The railway brings the layout
// back as soon as the station is heard again. Each test asserts what the simulated station ends with.

#include "ModelBench.h"
#include "mcanhandhelds/HandheldMaster.h"
#include "model/RailwayHandhelds.h"
#include "model/RailwayThrottles.h"

namespace stellwerk::model::test {
namespace {

using Power = sim::SimulatedStation::Power;

std::uint16_t stationSpeed(const ModelBench& bench, std::uint32_t loco) {
    const sim::SimulatedLoco* found = bench.station.loco(loco);
    return found ? found->speed : 0;
}

// Another controller on the station's bus (an MS2).
void otherController(ModelBench& bench, cs2::MessageBody body) {
    bench.station.receive(cs2::encode(cs2::Message{0, false, 0x2F11, std::move(body)}));
}

class AfterTrouble : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_TRUE(bench.start()); }

    void drive(std::uint32_t loco, int speed) {
        bench.railway.setSpeed(loco, speed);
        ASSERT_TRUE(waitFor([&] {
            const Locomotive* found = bench.railway.locomotive(loco);
            return found && found->speed() == speed && stationSpeed(bench, loco) == speed;
        }));
    }

    // Stalls the station, lets `command` fail (given up after every retry), then wakes the station and
    // waits until everything the railway sends afterwards has been answered.
    void failWhileStalled(const std::function<void()>& command) {
        bench.stall();
        QSignalSpy problems(&bench.railway, &Railway::problem);
        command();
        ASSERT_TRUE(waitFor([&] { return problems.count() >= 1; })) << "the command is given up";
        ASSERT_GT(bench.held.size(), 1U) << "its copies wait in the stalled station";
        bench.wake();
        ASSERT_TRUE(
            waitFor([&] { return corrections.count() >= 1 && bench.session.tracker().pendingCount() == 0; }));
        QTest::qWait(100);
    }

    Correction correction(int index = 0) const { return corrections.at(index).at(0).value<Correction>(); }

    ModelBench bench;
    QSignalSpy corrections{&bench.railway, &Railway::stateCorrected};
};

TEST_F(AfterTrouble, AGivenUpSpeedThatTheWakingStationCarriesOutIsStoppedAgain) {
    failWhileStalled([&] { bench.railway.setSpeed(Br86, 300); });
    EXPECT_EQ(stationSpeed(bench, Br86), 0) << "the station ends where the person last saw it";
    EXPECT_EQ(bench.railway.locomotive(Br86)->speed(), 0);
    EXPECT_TRUE(bench.railway.locomotive(Br86)->isSpeedReported());
    EXPECT_EQ(correction().target, CommandTarget::speed(Br86));
    EXPECT_EQ(correction().failedValue, 300);
    EXPECT_EQ(correction().sentValue, 0);
    EXPECT_TRUE(correction().carriedOutLate) << "the station was seen running it";
}

TEST_F(AfterTrouble, ARunningLocomotiveGoesBackToItsConfirmedSpeed) {
    drive(Br86, 400);
    failWhileStalled([&] { bench.railway.setSpeed(Br86, 700); });
    EXPECT_EQ(stationSpeed(bench, Br86), 400);
    EXPECT_EQ(bench.railway.locomotive(Br86)->speed(), 400);
}

TEST_F(AfterTrouble, ASlowerSpeedCarriedOutLateStaysAndIsTold) {
    drive(Br86, 600);
    failWhileStalled([&] { bench.railway.setSpeed(Br86, 200); });
    EXPECT_EQ(stationSpeed(bench, Br86), 200) << "never made faster to bring it back";
    EXPECT_EQ(bench.railway.locomotive(Br86)->speed(), 200);
    EXPECT_EQ(correction().failedValue, 200);
    EXPECT_FALSE(correction().sentValue.has_value());
    EXPECT_TRUE(correction().carriedOutLate);
}

TEST_F(AfterTrouble, AFunctionAndADirectionGoBackToWhatWasConfirmed) {
    failWhileStalled([&] {
        bench.railway.setFunction(Br86, 1, true);
        bench.railway.setDirection(Br86, cs2::Direction::Backward);
    });
    ASSERT_TRUE(
        waitFor([&] { return corrections.count() >= 2 && bench.session.tracker().pendingCount() == 0; }));
    EXPECT_EQ(bench.station.loco(Br86)->functions[1], 0);
    EXPECT_EQ(bench.station.loco(Br86)->direction, 1) << "forward";
    EXPECT_FALSE(bench.railway.locomotive(Br86)->functionOn(1));
    EXPECT_EQ(bench.railway.locomotive(Br86)->direction(), cs2::Direction::Forward);
}

TEST_F(AfterTrouble, AnAccessoryGoesBackToItsConfirmedPosition) {
    bench.railway.switchAccessory(1, 0);
    ASSERT_TRUE(waitFor([&] { return bench.railway.accessory(1)->isPositionReported(); }));
    failWhileStalled([&] { bench.railway.switchAccessory(1, 1); });
    EXPECT_EQ(bench.station.accessoryPosition(0x3000), 0);
    EXPECT_EQ(bench.railway.accessory(1)->position(), 0);
}

TEST_F(AfterTrouble, AGivenUpGoIsUndoneSoThatThePowerStaysOff) {
    bench.railway.stop();
    ASSERT_TRUE(waitFor([&] { return bench.railway.power() == station::PowerState::Stopped; }));
    failWhileStalled([&] { bench.railway.go(); });
    EXPECT_EQ(bench.station.power(), Power::Stopped);
    EXPECT_EQ(bench.railway.power(), station::PowerState::Stopped);
    EXPECT_EQ(correction().target, CommandTarget::power());
}

TEST_F(AfterTrouble, AGivenUpStopCarriedOutLateIsNeverUndoneByGo) {
    bench.railway.go();
    ASSERT_TRUE(waitFor([&] { return bench.railway.power() == station::PowerState::Running; }));
    failWhileStalled([&] { bench.railway.stop(); });
    EXPECT_EQ(bench.station.power(), Power::Stopped);
    EXPECT_EQ(bench.railway.power(), station::PowerState::Stopped);
    EXPECT_FALSE(correction().sentValue.has_value());
}

TEST_F(AfterTrouble, TheStopAftermathStopsALocomotiveWhoseFunctionCommandFailed) {
    drive(Br86, 400);
    bench.railway.setAftermath(Aftermath::StopLocomotives);
    failWhileStalled([&] { bench.railway.setFunction(Br86, 0, true); });
    EXPECT_EQ(stationSpeed(bench, Br86), 0);
    EXPECT_EQ(bench.railway.locomotive(Br86)->speed(), 0);
    EXPECT_EQ(correction().target, CommandTarget::speed(Br86));
}

TEST_F(AfterTrouble, ASpeedFromADeviceThrottleIsBroughtBackToo) {
    RailwayThrottles throttles(bench.railway);
    failWhileStalled([&] { throttles.setSpeed(Br86, 500); });
    EXPECT_EQ(stationSpeed(bench, Br86), 0);
}

TEST_F(AfterTrouble, ASpeedFromAHandheldIsBroughtBackToo) {
    mcanhandhelds::HandheldMaster master([](const std::vector<can::CanFrame>&) {});
    RailwayHandhelds handhelds(bench.railway, master);
    failWhileStalled([&] { handhelds.setSpeed(Br86, 500); });
    EXPECT_EQ(stationSpeed(bench, Br86), 0);
}

TEST_F(AfterTrouble, AnotherControllersChangeWhileItIsWatchedStands) {
    failWhileStalled([&] { bench.railway.setSpeed(Br86, 900); });
    ASSERT_EQ(stationSpeed(bench, Br86), 0);
    otherController(bench, cs2::LocoSpeed{cs2::LocId(Br86), 250}); // an MS2 drives it on
    ASSERT_TRUE(waitFor([&] { return bench.railway.locomotive(Br86)->speed() == 250; }));
    QTest::qWait(200);
    EXPECT_EQ(stationSpeed(bench, Br86), 250) << "the other controller's wish stands";
    EXPECT_EQ(corrections.count(), 1);
}

// "I don't trust what I see": every locomotive gets its confirmed speed and every state is read again.
TEST_F(AfterTrouble, BringingTheLayoutBackInStepSendsConfirmedSpeedsAndReadsEveryState) {
    drive(Br86, 300);
    bench.stall(); // nothing of what happens now on the station reaches the app
    bench.muted = true;
    bench.wake();
    otherController(bench, cs2::LocoSpeed{cs2::LocId(Br86), 900});
    otherController(bench, cs2::LocoSpeed{cs2::LocId(V100), 600});
    cs2::LocoFunction light;
    light.loco = cs2::LocId(Br86);
    light.function = 0;
    light.value = 1;
    otherController(bench, light);
    bench.muted = false;
    ASSERT_EQ(bench.railway.locomotive(Br86)->speed(), 300) << "the app has not seen it";
    QSignalSpy done(&bench.railway, &Railway::backInStep);
    bench.railway.bringBackInStep();
    EXPECT_TRUE(bench.railway.isBringingBackInStep());
    ASSERT_TRUE(waitFor([&] { return done.count() == 1; }));
    EXPECT_GT(done.first().at(0).toInt(), 0);
    EXPECT_EQ(done.first().at(1).toInt(), 0);
    EXPECT_FALSE(bench.railway.isBringingBackInStep());
    EXPECT_EQ(stationSpeed(bench, Br86), 300);
    EXPECT_EQ(stationSpeed(bench, V100), 0);
    EXPECT_EQ(bench.railway.locomotive(V100)->speed(), 0);
    EXPECT_TRUE(bench.railway.locomotive(Br86)->functionOn(0)) << "read again";
}

TEST_F(AfterTrouble, BringingTheLayoutBackInStepInTheStopAftermathStopsEveryLocomotive) {
    drive(Br86, 300);
    drive(V100, 200);
    bench.railway.setAftermath(Aftermath::StopLocomotives);
    QSignalSpy done(&bench.railway, &Railway::backInStep);
    bench.railway.bringBackInStep();
    ASSERT_TRUE(waitFor([&] { return done.count() == 1; }));
    EXPECT_EQ(stationSpeed(bench, Br86), 0);
    EXPECT_EQ(stationSpeed(bench, V100), 0);
}

} // namespace
} // namespace stellwerk::model::test
