// Issue 35's faults for the WiThrottle server: a WiThrottle client of the tests' own (as Engine Driver
// speaks) drives the demo's V 100 (MM, roster address S24) through the WiThrottle server in front of the
// railway the app holds, on the real stellwerk-sim, and the station is stopped (SIGSTOP) for 1 s and for 20
// s, or killed and started again on its port. Asserted: while the station is not heard the client is told the
// power is unknown (PPA2) and its speeds are refused with a message (HM) and never carried out later; the
// station ends with the speed it last confirmed before the trouble, asked of the station itself; the client's
// throttle ends showing that speed; once the station is heard and the phone switches the power on, it is told
// PPA1.

#include "../core/withrottleserver/WiThrottleTestClient.h"
#include "PhoneRig.h"

#include <QElapsedTimer>
#include <QTest>
#include <iostream>

namespace stellwerk::e2e {
namespace {

using withrottleserver::test::WiThrottleTestClient;

const std::string V100Key = "S24"; // MM keeps its address on the phones

withrottle::ThrottleAction speedTo(int speed) {
    return withrottle::ThrottleAction{'T', V100Key, withrottle::SetSpeed{speed}};
}

std::size_t powerLines(const WiThrottleTestClient& phone, withrottle::PowerState state) {
    std::size_t count = 0;
    for (const withrottle::PowerStatus& status : phone.all<withrottle::PowerStatus>())
        count += status.state == state ? 1 : 0;
    return count;
}

// A phone named "Annas Handy" that has acquired V 100 and drives it at 40 of 126, confirmed by the station.
std::unique_ptr<WiThrottleTestClient> phoneDrivingAt40(PhoneRig& rig, int& confirmedAt40) {
    auto phone = std::make_unique<WiThrottleTestClient>(rig.withrottle.port());
    EXPECT_TRUE(phone->waitFor<withrottle::HeartbeatInterval>());
    phone->send(withrottle::DeviceName{"Annas Handy"});
    phone->send(withrottle::AcquireLoco{'T', V100Key, withrottle::LocoAddress{24, false}, false});
    EXPECT_TRUE(phone->waitForText("MT+" + V100Key + "<;>"));
    phone->send(speedTo(40));
    EXPECT_TRUE(waitFor([&] { return phone->speedOf(V100Key) == 40 && rig.confirmedSpeed() > 0; }));
    confirmedAt40 = rig.confirmedSpeed();
    return phone;
}

// Sends a speed every 100 ms until `until` holds: 90..99 while the server still passes them on, 101..126 once
// it refuses them (the speeds sent after the first refusal was seen).
std::vector<int> keepDriving(PhoneRig& rig, WiThrottleTestClient& phone, const std::function<bool()>& until) {
    std::vector<int> refusedSpeeds;
    int sent = 0;
    QElapsedTimer last;
    waitFor(
        [&] {
            if (!last.isValid() || last.elapsed() >= 100) {
                const bool refusing = rig.withrottle.counters().refused > 0;
                const int speed = refusing ? 101 + sent % 26 : 90 + sent % 10;
                if (refusing)
                    refusedSpeeds.push_back(speed);
                phone.send(speedTo(speed));
                ++sent;
                last.start();
            }
            return until();
        },
        60000);
    return refusedSpeeds;
}

// After the trouble: the station ends at the speed confirmed before it, the app shows that, the phone's
// throttle shows 40 again, and no refused speed was ever shown to the phone.
void expectNothingReplayed(PhoneRig& rig, WiThrottleTestClient& phone, const std::vector<int>& refused,
                           int confirmedAt40) {
    QTest::qWait(1500); // a late copy of a speed would have arrived by now
    EXPECT_EQ(rig.stationSpeed(), confirmedAt40) << "the station ends where it was before the trouble";
    EXPECT_EQ(rig.confirmedSpeed(), confirmedAt40);
    EXPECT_TRUE(waitFor([&] { return phone.speedOf(V100Key) == 40; }))
        << "the phone ends showing the station's speed, not " << phone.speedOf(V100Key).value_or(-1);
    for (const withrottle::LocoStatus& status : phone.all<withrottle::LocoStatus>()) {
        if (const auto* speed = std::get_if<withrottle::SpeedState>(&status.update)) {
            EXPECT_EQ(std::count(refused.begin(), refused.end(), speed->speed), 0)
                << "shown speed " << speed->speed << ", which was refused";
        }
    }
}

// The CS2 cannot be asked for its track power: after the reset the phone is not told "on" until the station
// reports it. The phone's own "power on" is carried out and the station's report tells it PPA1.
void expectToldOnAgain(PhoneRig& rig, WiThrottleTestClient& phone, std::size_t onBefore) {
    ASSERT_FALSE(rig.binding.railway()->power().has_value()) << "the station has not reported its power";
    QTest::qWait(300);
    EXPECT_EQ(powerLines(phone, withrottle::PowerState::On), onBefore)
        << "never told on while it is not known";
    phone.send(withrottle::SetPower{true});
    EXPECT_TRUE(waitFor([&] { return powerLines(phone, withrottle::PowerState::On) > onBefore; }))
        << "told the power is on again once the station reports it";
}

class WiThrottleStalledStation : public ::testing::TestWithParam<int> {};

TEST_P(WiThrottleStalledStation, SpeedsAreRefusedNothingIsReplayedAndThePowerIsToldOnAgain) {
    const int stallMs = GetParam();
    PhoneRig rig;
    ASSERT_TRUE(rig.start());
    int confirmedAt40 = -1;
    auto phone = phoneDrivingAt40(rig, confirmedAt40);
    ASSERT_GT(confirmedAt40, 0);
    const std::size_t unknownBefore = powerLines(*phone, withrottle::PowerState::Unknown);

    ASSERT_TRUE(rig.sim->stall());
    QElapsedTimer stalled;
    stalled.start();
    const std::vector<int> refusedSpeeds =
        keepDriving(rig, *phone, [&] { return stalled.elapsed() >= stallMs; });
    EXPECT_GT(rig.withrottle.counters().refused, 0U) << "speeds are refused while the station is not heard";
    EXPECT_GT(powerLines(*phone, withrottle::PowerState::Unknown), unknownBefore) << "told PPA2";
    EXPECT_TRUE(phone->last<withrottle::ServerMessage>().has_value()) << "told why (HM)";
    const std::size_t onBefore = powerLines(*phone, withrottle::PowerState::On);
    const std::uint64_t refused = rig.withrottle.counters().refused;
    ASSERT_TRUE(rig.sim->wake());

    ASSERT_TRUE(rig.ready(stallMs + 6 * WaitMs)) << "the station is heard and read again";
    EXPECT_TRUE(phone->connected()) << "the phone kept its connection (it kept talking)";
    expectToldOnAgain(rig, *phone, onBefore);
    expectNothingReplayed(rig, *phone, refusedSpeeds, confirmedAt40);
    phone->send(speedTo(60));
    EXPECT_TRUE(waitFor([&] { return rig.confirmedSpeed() > confirmedAt40; })) << "it drives again";
    // Every speed sent after the first refusal was seen is refused; those sent before it was seen count too.
    EXPECT_GE(refused, refusedSpeeds.size() + 1);
    std::cout << "    " << stallMs / 1000 << " s: " << refused << " speeds refused during the stall"
              << std::endl;
}

// 1 s: shorter than the 3 s after which the station counts as silent, longer than a command's give-up.
// 20 s: past the silence and the connection's reset, and past the phone's 10 s heartbeat (it keeps talking).
INSTANTIATE_TEST_SUITE_P(Stall, WiThrottleStalledStation, ::testing::Values(1000, 20000),
                         [](const auto& info) { return "For" + std::to_string(info.param / 1000) + "s"; });

TEST(WiThrottleStationKilled, ThePhoneIsToldTheStationIsGoneAndNothingReachesTheNewOne) {
    PhoneRig rig;
    ASSERT_TRUE(rig.start());
    int confirmedAt40 = -1;
    auto phone = phoneDrivingAt40(rig, confirmedAt40);
    const std::size_t unknownBefore = powerLines(*phone, withrottle::PowerState::Unknown);
    rig.sim.reset(); // killed
    ASSERT_TRUE(waitFor([&] { return powerLines(*phone, withrottle::PowerState::Unknown) > unknownBefore; }))
        << "told the power is unknown";
    const std::size_t onBefore = powerLines(*phone, withrottle::PowerState::On);
    phone->send(speedTo(90));
    ASSERT_TRUE(waitFor([&] { return rig.withrottle.counters().refused > 0; })) << "refused while it is gone";
    ASSERT_TRUE(rig.startStation());
    ASSERT_TRUE(rig.ready(6 * WaitMs));
    expectToldOnAgain(rig, *phone, onBefore);
    QTest::qWait(1500);
    EXPECT_EQ(rig.stationSpeed(), 0) << "the refused speed never reached the new station";
    EXPECT_TRUE(phone->connected());
}

} // namespace
} // namespace stellwerk::e2e
