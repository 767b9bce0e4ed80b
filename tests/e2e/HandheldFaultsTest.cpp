// Issue 14 under faults: the station (the way to the handhelds) goes away just as Stellwerk passes on an
// MS1's speed, and comes back after 1 s and after 20 s. The given-up command never reaches the station,
// the handheld is not left showing a speed the station never took, and it is online again afterwards.

#include "HandheldRig.h"
#include "cs2/Codec.h"

#include <QTest>

namespace stellwerk::e2e {
namespace {

using connection::HandheldRole;
using mcanhandhelds::HandheldState;
using sim::SimulatedMs1;

// Whether the frames carry the CS2 command that sets the locomotive's speed.
bool setsSpeed(const std::vector<can::CanFrame>& frames, std::uint32_t locId, std::uint16_t speed) {
    for (const can::CanFrame& frame : frames) {
        const auto message = cs2::decode(frame);
        const auto* body = message ? std::get_if<cs2::LocoSpeed>(&message->body) : nullptr;
        if (body && !message->response && body->loco.value() == locId && body->speed == speed)
            return true;
    }
    return false;
}

class HandheldStationGoneMidCommand : public ::testing::TestWithParam<int> {};

TEST_P(HandheldStationGoneMidCommand, TheGivenUpSpeedNeverArrivesAndTheHandheldShowsTheStationsSpeed) {
    const int outageMs = GetParam();
    HandheldBus station(Wire::Udp, false);
    ASSERT_TRUE(station.listen());
    StationLog log(station.station);
    HandheldApp app(HandheldRole::Master);
    app.connection.connectTo(station.url());
    ASSERT_TRUE(app.ready());
    station.first.plugIn();
    ASSERT_TRUE(drivesFirstLoco(station.first));
    const std::uint32_t locId = *app.handheld(FirstMs1)->loco;
    QObject::connect(&app.connection.buses(), &connection::ConnectionBuses::stationFramesSeen,
                     &app.connection, [&](const std::vector<can::CanFrame>& frames, bool outgoing) {
                         if (outgoing && station.server && setsSpeed(frames, locId, 504))
                             station.stopServer(); // the station goes with the command on its way
                     });

    ASSERT_TRUE(station.first.setSpeed(64, SimulatedMs1::Direction::Forward));
    ASSERT_TRUE(waitFor([&] { return !station.server; })) << "Stellwerk passed the speed on";
    ASSERT_TRUE(waitFor([&] { return !app.railway->isStateReported(); }));
    EXPECT_EQ(app.loco(locId).speed(), 0) << "the speed the station never took is not shown";
    ASSERT_TRUE(waitFor([&] { return station.first.phase() != SimulatedMs1::Phase::Online; }))
        << "the handheld misses its master";

    QTest::qWait(outageMs);
    ASSERT_TRUE(station.listen());
    ASSERT_TRUE(app.ready(outageMs + 4 * WaitMs));
    ASSERT_TRUE(waitFor([&] { return app.shows(FirstMs1, HandheldState::Online); }, 3 * WaitMs))
        << "logged in again";
    ASSERT_TRUE(waitFor([&] { return station.first.shownLoco() != nullptr; }, 3 * WaitMs))
        << "it takes the first locomotive of its stack again";
    QTest::qWait(300);
    EXPECT_FALSE(log.received(locId, 504)) << "a given-up command reached the station";
    EXPECT_EQ(station.station.loco(locId)->speed, 0);
    EXPECT_EQ(app.loco(locId).speed(), 0);
    EXPECT_EQ(station.first.shownLoco()->speed, 0) << "the handheld shows the station's speed";

    ASSERT_TRUE(station.first.setSpeed(10, SimulatedMs1::Direction::Forward));
    ASSERT_TRUE(waitFor([&] { return log.received(locId, 79); })) << "and drives again";
}

// 1 s: back before the handheld's login retries grow. 20 s: past every retry and give-up deadline.
INSTANTIATE_TEST_SUITE_P(BackAfter, HandheldStationGoneMidCommand, ::testing::Values(1000, 20000),
                         [](const auto& info) { return std::to_string(info.param / 1000) + "s"; });

} // namespace
} // namespace stellwerk::e2e
