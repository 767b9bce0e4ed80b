// Issue 14 end to end: an MS1 on the station's bus drives the layout with Stellwerk as its master, over UDP
// and over a CAN adapter (virtualcan); with a Central Station on the bus, Stellwerk only watches; another
// master speaking makes it fall silent; a second handheld cannot steal a locomotive; a handheld pulled out
// goes silent and then offline. Asserted: what reached the station, what the handheld shows and what the
// app claims.

#include "HandheldRig.h"
#include "cs2/Codec.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

namespace stellwerk::e2e {
namespace {

using connection::HandheldRole;
using mcanhandhelds::HandheldState;
using mcanhandhelds::Watching;
using sim::SimulatedMs1;

class HandheldOverWire : public ::testing::TestWithParam<Wire> {};

TEST_P(HandheldOverWire, AnMs1LogsInAtStellwerkAndDrivesTheStationsLocomotive) {
    HandheldBus station(GetParam(), false);
    ASSERT_TRUE(station.listen());
    StationLog log(station.station);
    HandheldApp app(HandheldRole::Automatic);
    app.connection.connectTo(station.url());
    ASSERT_TRUE(app.ready());
    ASSERT_TRUE(waitFor([&] { return app.master().isMaster(); })) << "a Gleisbox is no master: Stellwerk is";

    station.first.plugIn();
    ASSERT_TRUE(waitFor([&] { return app.shows(FirstMs1, HandheldState::Online); }));
    EXPECT_EQ(app.handheld(FirstMs1)->name, QStringLiteral("MS1 A"));
    ASSERT_TRUE(drivesFirstLoco(station.first));
    ASSERT_TRUE(waitFor([&] { return app.handheld(FirstMs1)->loco.has_value(); }));
    const std::uint32_t locId = *app.handheld(FirstMs1)->loco;
    EXPECT_EQ(app.handheld(FirstMs1)->locoName.toStdString(), station.first.shownLoco()->name);

    ASSERT_TRUE(station.first.setSpeed(64, SimulatedMs1::Direction::Forward));
    ASSERT_TRUE(waitFor([&] { return log.received(locId, 504); })) << "64 of 127 steps is 504 of 1000";
    ASSERT_TRUE(
        waitFor([&] { return app.loco(locId).speed() == 504 && app.handheld(FirstMs1)->speed == 64; }));
    EXPECT_EQ(station.station.loco(locId)->speed, 504);

    app.railway->setSpeed(locId, 1000); // the app's throttle
    ASSERT_TRUE(waitFor([&] { return station.first.shownLoco()->speed == 127; }))
        << "a change made elsewhere reaches the handheld that shows the locomotive";
    EXPECT_EQ(station.station.loco(locId)->speed, 1000);
    EXPECT_EQ(app.master().counters().unexpected, 0u);
}

// Both MS1s start with the same stack; the first one's locomotive is refused to the second.
TEST_P(HandheldOverWire, ASecondMs1CannotTakeTheLocomotiveTheFirstDrives) {
    HandheldBus station(GetParam(), false);
    ASSERT_TRUE(station.listen());
    StationLog log(station.station);
    HandheldApp app(HandheldRole::Master);
    app.connection.connectTo(station.url());
    ASSERT_TRUE(app.ready());
    station.first.plugIn();
    station.second.plugIn();
    ASSERT_TRUE(drivesFirstLoco(station.first));
    ASSERT_TRUE(waitFor([&] { return app.shows(SecondMs1, HandheldState::Online); }));
    ASSERT_TRUE(waitFor([&] { return !station.second.memory().stack.empty(); }));
    const std::uint32_t locId = *app.handheld(FirstMs1)->loco;

    QSignalSpy refused(&station.second, &SimulatedMs1::locoRefused);
    ASSERT_TRUE(station.second.takeLoco(0));
    ASSERT_TRUE(waitFor([&] { return refused.count() == 1; }));
    EXPECT_NE(station.second.memory().control, sim::Ms1Control::Granted);
    EXPECT_FALSE(station.second.setSpeed(100, SimulatedMs1::Direction::Forward)) << "it may only watch";
    QTest::qWait(200);
    EXPECT_TRUE(log.speedsSet(locId).empty()) << "nothing of the second handheld reached the station";
    EXPECT_TRUE(app.handheld(SecondMs1)->locoRefused);
    EXPECT_EQ(app.handheld(FirstMs1)->loco, locId) << "the first one keeps it";
}

TEST_P(HandheldOverWire, AnMs1PulledOutGoesSilentThenOfflineAndFreesItsLocomotive) {
    HandheldBus station(GetParam(), false);
    ASSERT_TRUE(station.listen());
    HandheldApp app(HandheldRole::Master);
    app.connection.connectTo(station.url());
    ASSERT_TRUE(app.ready());
    station.first.plugIn();
    ASSERT_TRUE(drivesFirstLoco(station.first));
    std::vector<HandheldState> states;
    QObject::connect(&app.master(), &mcanhandhelds::HandheldMaster::handheldsChanged, &app.connection, [&] {
        if (const auto h = app.handheld(FirstMs1); h && (states.empty() || states.back() != h->state))
            states.push_back(h->state);
    });

    QElapsedTimer sinceUnplugged;
    station.first.unplug();
    sinceUnplugged.start();
    ASSERT_TRUE(
        waitFor([&] { return !app.handheld(FirstMs1) || app.shows(FirstMs1, HandheldState::Offline); }));
    const mcanhandhelds::MasterSettings documented = quickMaster(); // 7.5 s, then 30 polls 1 s apart, scaled
    EXPECT_GE(sinceUnplugged.elapsed(), documented.silentAfter.count())
        << "not given up before it went silent";
    EXPECT_LT(sinceUnplugged.elapsed(),
              (documented.silentAfter + documented.masterPolls * documented.masterPollEvery +
               std::chrono::milliseconds(WaitMs / 5))
                  .count())
        << "noticed within the documented time";
    ASSERT_FALSE(states.empty());
    EXPECT_EQ(states.front(), HandheldState::Silent) << "polled before it is given up";
    station.second.plugIn();
    ASSERT_TRUE(drivesFirstLoco(station.second)) << "the locomotive is free again";

    station.first.plugIn();
    ASSERT_TRUE(waitFor([&] { return app.shows(FirstMs1, HandheldState::Online); }))
        << "back after a new login";
}

// With a Central Station on the bus, it is the handhelds' master: Stellwerk only watches, sends no M-CAN
// frame, and still shows the handheld and what it drives.
TEST_P(HandheldOverWire, WithTheStationAsMasterStellwerkWatchesAndShowsTheHandheld) {
    HandheldBus station(GetParam(), true);
    ASSERT_TRUE(station.listen());
    StationLog log(station.station);
    HandheldApp app(HandheldRole::Automatic);
    app.connection.connectTo(station.url());
    ASSERT_TRUE(app.ready());
    ASSERT_TRUE(waitFor([&] { return app.master().watching() == Watching::CentralStation; }));
    const std::uint32_t running = station.station.layout().locomotives().locomotives.front().uid;
    station.bus.putFromOutside(
        {cs2::encode(cs2::Message{0, false, 0x2F11, cs2::LocoSpeed{cs2::LocId(running), 500}})});
    ASSERT_TRUE(waitFor(
        [&] { return station.station.loco(running) && station.station.loco(running)->speed == 500; }));

    station.first.plugIn();
    ASSERT_TRUE(drivesFirstLoco(station.first));
    ASSERT_TRUE(waitFor([&] { return app.shows(FirstMs1, HandheldState::Online); }));
    EXPECT_FALSE(app.handheld(FirstMs1)->ours);
    EXPECT_EQ(station.first.shownLoco()->speed, 64) << "it took a running locomotive: 500 of 1000 is step 64";
    EXPECT_TRUE(waitFor([&] { return app.handheld(FirstMs1)->speed == 64; }))
        << "the watcher shows the speed its master told it for the locomotive it took";
    ASSERT_TRUE(station.first.setSpeed(32, SimulatedMs1::Direction::Forward));
    ASSERT_TRUE(waitFor([&] { return app.handheld(FirstMs1)->speed == 32; }));
    ASSERT_TRUE(waitFor([&] { return !app.handheld(FirstMs1)->locoName.isEmpty(); }))
        << "the watcher knows the locomotive by the name its master told the handheld";
    const QString name = app.handheld(FirstMs1)->locoName;
    EXPECT_EQ(name.toStdString(), station.first.shownLoco()->name);
    const model::Locomotive* loco = nullptr;
    for (const model::Locomotive& l : app.railway->state().locomotives().items())
        if (l.displayName() == name)
            loco = &l;
    ASSERT_NE(loco, nullptr) << name.toStdString();
    const std::uint32_t locId = loco->id().value();
    EXPECT_TRUE(log.received(locId, 252)) << "the station drove it itself";
    ASSERT_TRUE(waitFor([&] { return app.loco(locId).speed() == 252; }));
    station.bus.putFromOutside(
        {cs2::encode(cs2::Message{0, false, 0x2F11, cs2::LocoSpeed{cs2::LocId(locId), 1000}})});
    ASSERT_TRUE(waitFor([&] { return station.first.shownLoco()->speed == 127; })) << "its master told it";
    EXPECT_TRUE(waitFor([&] { return app.handheld(FirstMs1)->speed == 127; }))
        << "the watcher shows what the master told the handheld";
    EXPECT_TRUE(app.mcanSent.empty()) << "Stellwerk answered a handheld of another master";
}

// Stellwerk is the master; then a Central Station's master side joins the bus and answers a login before
// it heard Stellwerk: Stellwerk stops answering at once, says why, and still shows the handheld.
TEST_P(HandheldOverWire, FallsSilentWhenAnotherMasterSpeaks) {
    HandheldBus station(GetParam(), false);
    ASSERT_TRUE(station.listen());
    HandheldApp app(HandheldRole::Master);
    app.connection.connectTo(station.url());
    ASSERT_TRUE(app.ready());
    station.first.plugIn();
    ASSERT_TRUE(waitFor([&] { return app.shows(FirstMs1, HandheldState::Online); }));
    QSignalSpy masterChanged(&app.master(), &mcanhandhelds::HandheldMaster::masterChanged);

    station.addStationMaster();
    station.stationMaster->receive(mcan::encode(mcan::LoginRequest{0, 0x00, 0})); // it answers a login
    ASSERT_TRUE(waitFor([&] { return app.master().watching() == Watching::AnotherMaster; }));
    EXPECT_FALSE(app.master().isMaster());
    EXPECT_EQ(app.master().otherMasterNode(), 0) << "a login reply does not say the master's node";
    ASSERT_GE(masterChanged.count(), 1);
    EXPECT_FALSE(masterChanged.last().at(0).toBool());
    const std::size_t sentWhenSilent = app.mcanSent.size();
    station.second.plugIn();
    QTest::qWait(400);
    EXPECT_EQ(app.mcanSent.size(), sentWhenSilent) << "Stellwerk answered after another master spoke";
    EXPECT_TRUE(app.handheld(FirstMs1).has_value()) << "the handheld is still shown";
}

INSTANTIATE_TEST_SUITE_P(Wires, HandheldOverWire, ::testing::Values(Wire::Udp, Wire::VirtualCan),
                         [](const auto& info) { return wireName(info.param); });

// Another program on the CAN bus sends M-CAN frames nobody can explain: they are counted and never end the
// session of the handheld that is online.
TEST(HandheldMaster, GarbageFromAnotherProgramOnTheBusIsCountedAndHarmsNoSession) {
    HandheldBus station(Wire::VirtualCan, false);
    ASSERT_TRUE(station.listen());
    HandheldApp app(HandheldRole::Master);
    app.connection.connectTo(station.url());
    ASSERT_TRUE(app.ready());
    station.first.plugIn();
    ASSERT_TRUE(drivesFirstLoco(station.first));
    const std::uint32_t locId = *app.handheld(FirstMs1)->loco;
    auto other = transport::createTransport(virtualBus());
    other->open();
    ASSERT_TRUE(waitFor([&] { return other->state() == transport::Transport::State::Connected; }));

    const std::uint64_t before = app.master().counters().unexpected;
    other->send(mcan::encode(mcan::LoginRequest{2, 0x04, 29})); // stage 1 skipped, a MID nobody gave
    other->send(mcan::encode(mcan::Poll{{mcan::prio::Master, 1, 77}, 76})); // a node nobody was given
    other->send(can::CanFrame::extendedFrame(0x18000DAB, std::vector<std::uint8_t>{9})); // no known form
    ASSERT_TRUE(waitFor([&] { return app.master().counters().unexpected >= before + 2; }));
    QTest::qWait(200);
    EXPECT_TRUE(app.shows(FirstMs1, HandheldState::Online));
    ASSERT_TRUE(station.first.setSpeed(20, SimulatedMs1::Direction::Forward));
    ASSERT_TRUE(waitFor([&] { return station.station.loco(locId)->speed == 157; })) << "still drives";
}

} // namespace
} // namespace stellwerk::e2e
