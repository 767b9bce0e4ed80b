// Every frame on the bus updates the state, including other controllers' commands once the station
// confirmed them (3.4: "Durch Auswerten der Fahrbefehle (Antworten) kann eine Anzeige stetig
// aktualisiert werden"), batched: one update per received batch.

#include "ScriptedStation.h"

namespace stellwerk::station::test {
namespace {

constexpr std::uint16_t OtherController = 0x2F55;

TEST(StationEvents, OtherControllersSpeedCommandUpdatesTheSpeedOnceConfirmed) {
    Bench bench;
    UpdateLog log(bench.session);
    bench.station.sendToApp({frame(0x04, false, OtherController, {0, 0, 0x40, 0x06, 0x01, 0xF4})});
    ASSERT_TRUE(waitFor([&] { return bench.session.counters().frames == 1; }));
    EXPECT_TRUE(log.batches.empty()) << "a command alone is not yet carried out";
    bench.station.sendToApp({frame(0x04, true, ScriptedStation::Hash, {0, 0, 0x40, 0x06, 0x01, 0xF4})});
    ASSERT_TRUE(waitFor([&] { return log.batches.size() == 1; }));
    ASSERT_EQ(log.batches[0].speeds.size(), 1u);
    EXPECT_EQ(log.batches[0].speeds[0].loco, cs2::LocId(0x4006));
    EXPECT_EQ(log.batches[0].speeds[0].speed, 500);
}

TEST(StationEvents, DirectionFunctionAccessoryAndPowerAnswersArriveAsOneBatch) {
    Bench bench;
    UpdateLog log(bench.session);
    const std::uint16_t h = ScriptedStation::Hash;
    bench.station.sendToApp({
        frame(0x05, true, h, {0, 0, 0x40, 0x06, 2}),                      // backward
        frame(0x06, true, h, {0, 0, 0x40, 0x06, 4, 1}),                   // F4 on
        frame(0x0B, true, h, {0, 0, 0x30, 0x02, 1, 0}),                   // MM accessory 3, green
        frame(0x00, true, h, {0x47, 0x43, 0xF5, 0xDA, 0x01}),             // go
        frame(0x11, true, h, {0x00, 0x01, 0x00, 0x07, 0, 1, 0x00, 0x0A}), // contact 7 occupied
    });
    ASSERT_TRUE(waitFor([&] { return !log.batches.empty(); }));
    QTest::qWait(20);
    ASSERT_EQ(log.batches.size(), 1u);
    const StationUpdates& u = log.batches[0];
    ASSERT_EQ(u.directions.size(), 1u);
    EXPECT_EQ(u.directions[0].direction, cs2::Direction::Backward);
    ASSERT_EQ(u.functions.size(), 1u);
    EXPECT_EQ(u.functions[0].function, 4);
    EXPECT_EQ(u.functions[0].value, 1);
    ASSERT_EQ(u.accessories.size(), 1u);
    EXPECT_EQ(u.accessories[0].article, cs2::LocId(0x3002));
    EXPECT_EQ(u.accessories[0].position, 1);
    ASSERT_EQ(u.power.size(), 1u);
    EXPECT_EQ(u.power[0].state, PowerState::Running);
    ASSERT_EQ(u.contacts.size(), 1u);
    EXPECT_EQ(u.contacts[0].device, 1);
    EXPECT_EQ(u.contacts[0].contact, 7);
    EXPECT_TRUE(u.contacts[0].occupied);
    EXPECT_FALSE(u.contacts[0].wasOccupied);
}

TEST(StationEvents, PingAnswersListDevicesInTheDirectory) {
    Bench bench;
    UpdateLog log(bench.session);
    bench.station.devices.push_back({0x43533208, 4, 1, 0xFFFF});
    bench.session.ping();
    ASSERT_TRUE(waitFor([&] { return bench.session.devices().size() == 2; }));
    const auto* gleisbox = bench.session.devices().find(ScriptedStation::Uid);
    ASSERT_NE(gleisbox, nullptr);
    EXPECT_EQ(gleisbox->identity.deviceType, 0x0010);
    EXPECT_EQ(gleisbox->identity.versionMinor, 0x27);
    ASSERT_FALSE(log.batches.empty());
    EXPECT_EQ(log.batches[0].devices.size(), 2u);
}

TEST(StationEvents, UndecodableFramesAreCountedNotPassedOn) {
    Bench bench;
    UpdateLog log(bench.session);
    bench.station.sendToApp({frame(0x04, true, ScriptedStation::Hash, {0, 0, 0x40})}); // speed needs 4 or 6
    ASSERT_TRUE(waitFor([&] { return bench.session.counters().undecodable == 1; }));
    EXPECT_TRUE(log.batches.empty());
}

} // namespace
} // namespace stellwerk::station::test
