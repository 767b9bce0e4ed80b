// The simulated CS2 as the M-CAN master of the MS1 handhelds on its bus (StationHandhelds), as a real CS2
// is: an MS1 logs in to it, drives the station's locomotives and switches its track power, and sees what
// other controllers change; told not to be their master, the station answers a ping as a Gleisbox.

#include "Ms1TestSupport.h"
#include "cs2/Codec.h"
#include "cs2/Request.h"
#include "sim/SimulatedBus.h"
#include "sim/SimulatedStation.h"
#include "sim/StationHandhelds.h"
#include "sim/StationLayout.h"

#include <memory>

namespace stellwerk::sim::test {
namespace {

// A CS2 with its master side and one MS1 on a simulated bus; the master's clocks fast for tests.
class StationAsMaster : public ::testing::Test {
protected:
    StationAsMaster() : station(StationLayout::demo()), master(station, fastMaster()), ms1(fastMs1()) {
        bus.attach(station);
        bus.attach(master);
        bus.attach(ms1);
        QObject::connect(&bus, &SimulatedBus::framesCarried, &bus,
                         [this](const std::vector<CanFrame>& batch) {
                             carried.insert(carried.end(), batch.begin(), batch.end());
                         });
    }

    static mcanhandhelds::MasterSettings fastMaster() {
        mcanhandhelds::MasterSettings settings;
        settings.silentAfter = std::chrono::milliseconds(300);
        settings.masterPollEvery = std::chrono::milliseconds(20);
        settings.masterPolls = 5;
        settings.tick = std::chrono::milliseconds(10);
        return settings;
    }

    // The MS1 logged in, upgraded and driving the first locomotive of its stack.
    void driveFirstLoco() {
        ms1.plugIn();
        ASSERT_TRUE(waitFor([&] { return ms1.phase() == SimulatedMs1::Phase::Online; }));
        ASSERT_TRUE(waitFor([&] { return !ms1.memory().stack.empty(); }));
        ASSERT_TRUE(ms1.takeLoco(0));
        ASSERT_TRUE(waitFor([&] { return ms1.memory().control == Ms1Control::Granted; }));
    }

    std::uint32_t firstLocId() const { return station.layout().locomotives().locomotives.front().uid; }

    // The CS2 responses about a locomotive's speed the station put on the bus.
    std::vector<std::uint16_t> speedReports(std::uint32_t locId) const {
        std::vector<std::uint16_t> speeds;
        for (const CanFrame& f : carried) {
            if (!f.extended || !cs2::isResponse(f))
                continue;
            const auto decoded = cs2::decode(f);
            if (!decoded)
                continue;
            if (const auto* speed = std::get_if<cs2::LocoSpeed>(&decoded.value().body))
                if (speed->loco.value() == locId && speed->speed)
                    speeds.push_back(*speed->speed);
        }
        return speeds;
    }

    SimulatedBus bus;
    SimulatedStation station;
    StationHandhelds master;
    SimulatedMs1 ms1;
    std::vector<CanFrame> carried;
};

TEST_F(StationAsMaster, AnMs1LogsInAndGetsTheStationsLocomotivesOnItsStack) {
    ms1.plugIn();
    ASSERT_TRUE(waitFor([&] { return ms1.phase() == SimulatedMs1::Phase::Online; }));
    ASSERT_TRUE(waitFor([&] { return !ms1.memory().stack.empty(); }));
    EXPECT_EQ(ms1.memory().link.node, 43) << "the first slave node of a master on node 42";
    const auto& locos = station.layout().locomotives().locomotives;
    ASSERT_FALSE(locos.empty());
    ASSERT_TRUE(waitFor([&] { return ms1.memory().stack.front().name == locos.front().name; }))
        << "the stack shows the station's first locomotive by its name";
    ASSERT_EQ(master.master().handhelds().size(), 1u);
    EXPECT_EQ(master.master().handhelds().front().uid, ms1.identity().uid);
}

TEST_F(StationAsMaster, TheMs1sSpeedKeyDrivesTheStationsLocomotive) {
    driveFirstLoco();
    ASSERT_TRUE(ms1.setSpeed(64, SimulatedMs1::Direction::Forward));
    const std::uint32_t locId = firstLocId();
    ASSERT_TRUE(waitFor([&] { return station.loco(locId) && station.loco(locId)->speed > 0; }));
    EXPECT_EQ(station.loco(locId)->speed, 504) << "64 of 127 steps is 504 of 1000";
    ASSERT_TRUE(waitFor([&] { return !speedReports(locId).empty(); }))
        << "the station reports the change on its bus, as for any controller";
    EXPECT_EQ(speedReports(locId).back(), 504);

    ASSERT_TRUE(ms1.setSpeed(0, SimulatedMs1::Direction::Reverse));
    ASSERT_TRUE(waitFor([&] { return station.loco(locId)->direction == 2; }));
    EXPECT_EQ(station.loco(locId)->speed, 0);
}

TEST_F(StationAsMaster, AFunctionKeySwitchesTheStationsFunction) {
    driveFirstLoco();
    ASSERT_FALSE(ms1.shownLoco()->functions.empty());
    ASSERT_TRUE(ms1.setFunction(0, true));
    const std::uint32_t locId = firstLocId();
    ASSERT_TRUE(waitFor([&] { return station.loco(locId) && station.loco(locId)->functions[0] == 1; }));
}

TEST_F(StationAsMaster, AnotherControllersChangeReachesTheMs1) {
    driveFirstLoco();
    const std::uint32_t locId = firstLocId();
    CanFrame outside = cs2::encode(cs2::request(cs2::LocoSpeed{cs2::LocId(locId), std::uint16_t(1000)}));
    bus.putFromOutside({outside}); // the app's throttle, through the server
    ASSERT_TRUE(waitFor([&] { return ms1.shownLoco()->speed == 127; }))
        << "full speed elsewhere shows as step 127 on the handheld";
}

TEST_F(StationAsMaster, StopAndGoKeysSwitchTheStationsTrackPowerAndTheMs1ShowsIt) {
    driveFirstLoco();
    ASSERT_TRUE(ms1.pressGo());
    ASSERT_TRUE(waitFor([&] { return station.power() == SimulatedStation::Power::Running; }));
    ASSERT_TRUE(waitFor([&] { return !ms1.memory().stopped; }));
    ASSERT_TRUE(ms1.pressStop());
    ASSERT_TRUE(waitFor([&] { return station.power() == SimulatedStation::Power::Stopped; }));

    bus.putFromOutside({cs2::encode(cs2::request(cs2::SystemGo{0}))});
    ASSERT_TRUE(waitFor([&] { return station.power() == SimulatedStation::Power::Running; }));
    EXPECT_TRUE(waitFor([&] { return !ms1.memory().stopped; })) << "Go from elsewhere lifts the MS1's stop";
}

TEST_F(StationAsMaster, AnOverloadShowsAsAShortCircuitOnTheMs1UntilGo) {
    driveFirstLoco();
    bus.putFromOutside({cs2::encode(cs2::request(cs2::SystemGo{0}))});
    ASSERT_TRUE(waitFor([&] { return station.power() == SimulatedStation::Power::Running; }));
    station.setTrackLoad(100000); // far above the current limit: the station reports an overload
    ASSERT_TRUE(waitFor([&] { return ms1.memory().shortCircuit; })) << "the MS1 shows the short circuit";
    EXPECT_TRUE(ms1.memory().stopped);
    station.setTrackLoad(0);
    ASSERT_TRUE(ms1.pressGo());
    ASSERT_TRUE(waitFor([&] { return !ms1.memory().shortCircuit && !ms1.memory().stopped; }));
}

TEST_F(StationAsMaster, AnMs1PulledOutIsDroppedAndLogsInAgainWhenPluggedBackIn) {
    driveFirstLoco();
    ms1.unplug();
    ASSERT_TRUE(waitFor([&] {
        return master.master().handhelds().empty() ||
               master.master().handhelds().front().state == mcanhandhelds::HandheldState::Offline;
    }));
    ms1.plugIn();
    ASSERT_TRUE(waitFor([&] { return ms1.phase() == SimulatedMs1::Phase::Online; }));
}

// A ping's answer says who the station is: a Central Station (the handhelds' master) or, with
// handheldMaster off, a Gleisbox, so that a program on the bus may be their master.
std::uint16_t pingedDeviceType(bool handheldMaster) {
    SimulatedStation::Options options;
    options.handheldMaster = handheldMaster;
    SimulatedStation station(StationLayout::demo(), options);
    Emitted emitted(station);
    station.receive(cs2::encode(cs2::request(cs2::Ping{})));
    for (const CanFrame& f : emitted.all)
        if (const auto decoded = cs2::decode(f))
            if (const auto* ping = std::get_if<cs2::Ping>(&decoded.value().body); ping && ping->identity)
                return ping->identity->deviceType;
    return 0;
}

TEST(StationPing, AStationThatIsNoHandheldMasterAnswersAsAGleisbox) {
    EXPECT_EQ(pingedDeviceType(true), 0xFFFF);
    EXPECT_EQ(pingedDeviceType(false), 0x0010);
}

} // namespace
} // namespace stellwerk::sim::test
