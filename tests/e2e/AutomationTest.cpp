// Issue 34, proven on the simulator: automatic trains driven by the automation over a real TCP socket
// against the simulated CS2, whose accident counters are the referee. Simulated minutes on the demo, the
// same trains driven without automation for comparison, and the faults: a ghost on a reserved way, an
// external switch of a reserved turnout, an overrun, the station falling silent. Then mixed operation
// (another controller or this program's throttle takes a train), schedules, turning round, and two trains
// running opposite ways over the single line.

#include "AutomationRig.h"
#include "automation/Schedule.h"
#include "can/FrameText.h"
#include "cs2/Codec.h"
#include "cs2config/Diagnostics.h"
#include "sim/TrainPlacement.h"

#include <gtest/gtest.h>

namespace stellwerk::e2e {
namespace {

using automation::AutomationEvent;
using automation::TrainState;
using Kind = automation::AutomationEvent::Kind;
using trackgraph::End;

constexpr std::uint32_t Br218 = 0x4001, Ice = 0x4002, V100 = 0x0018;

// BR 218 on Gleis 1, the ICE on Block 2 and the V 100 on Gleis 2, all round the loop; the Köf in the siding.
std::vector<sim::TrainPlacement> demoTrains() {
    return sim::demoPlacements();
}

void otherControllerSends(sim::SimulatedStation& station, cs2::MessageBody body) {
    station.receive(cs2::encode(cs2::Message{0, false, 0x2F11, std::move(body)}));
}

TEST(Automation, ThreeTrainsRunThreeSimulatedMinutesOnTheDemoWithoutAccident) {
    AutomationRig rig;
    ASSERT_TRUE(rig.start(demoTrains()));
    rig.startAutomation();
    rig.run(std::chrono::minutes(3));
    EXPECT_TRUE(rig.accidents.empty()) << rig.accidents.front() << "\n" << rig.eventLog();
    EXPECT_EQ(rig.movement->accidents().total(), 0);
    EXPECT_EQ(rig.automation->dispatcher().faults(), 0) << rig.eventLog();
    EXPECT_GE(rig.automation->dispatcher().blockMoves(), 40) << rig.eventLog();
    for (const std::uint32_t locId : {Br218, Ice, V100})
        EXPECT_GE(rig.count(Kind::Arrived, locId), 5) << locId << "\n" << rig.eventLog();
}

// The referee can fail: the same trains at the same speed for the same time, without the automation.
TEST(Automation, TheSameTrainsWithoutAutomationCollide) {
    AutomationRig rig;
    ASSERT_TRUE(rig.start(demoTrains()));
    for (const std::uint32_t locId : {Br218, Ice, V100})
        rig.railway->setSpeed(locId, automation::SpeedProfile{}.travel);
    rig.settle();
    rig.automation.reset();
    rig.graph.reset();
    for (int step = 0; step < 3 * 60 * 20 && rig.movement->accidents().total() == 0; ++step)
        rig.movement->advance(AutomationRig::Step);
    EXPECT_GT(rig.movement->accidents().total(), 0);
}

// An unknown occupant appears in the block a train has reserved: the train stops at once, nobody collides.
TEST(Automation, AGhostOnTheReservedWayStopsTheTrain) {
    AutomationRig rig;
    ASSERT_TRUE(rig.start({{Br218, 1, End::B}}));
    rig.startAutomation();
    for (int i = 0; i < 40 && rig.count(Kind::Departed, Br218) == 0; ++i)
        rig.run(AutomationRig::Step);
    ASSERT_EQ(rig.count(Kind::Departed, Br218), 1) << rig.eventLog();
    const trackgraph::Block& destination =
        rig.graph->block(*rig.automation->dispatcher().train(Br218)->destination);
    const trackgraph::ContactKey ghost = destination.contacts.front().contact;
    rig.rig.station.setContact(std::uint16_t(ghost.device), std::uint16_t(ghost.number), true);
    rig.run(std::chrono::milliseconds(500));
    EXPECT_EQ(rig.count(Kind::Ghost), 1) << rig.eventLog();
    EXPECT_EQ(rig.count(Kind::Fault, Br218), 1) << rig.eventLog();
    EXPECT_EQ(rig.automation->dispatcher().train(Br218)->state, TrainState::Fault);
    EXPECT_EQ(rig.rig.station.loco(Br218)->speed, 0);
    const int blockMoves = rig.automation->dispatcher().blockMoves();
    rig.run(std::chrono::seconds(20));
    EXPECT_EQ(rig.automation->dispatcher().blockMoves(), blockMoves) << rig.eventLog();
    EXPECT_EQ(rig.movement->accidents().total(), 0);
}

// Another controller throws turnout 2 while the BR 218's way over it to Ausfahrt Ost is reserved.
TEST(Automation, AnExternalSwitchOfAReservedTurnoutStopsTheTrain) {
    AutomationRig rig;
    ASSERT_TRUE(rig.start({{Br218, 1, End::B}}));
    rig.startAutomation();
    for (int i = 0; i < 40 && rig.count(Kind::Departed, Br218) == 0; ++i)
        rig.run(AutomationRig::Step);
    ASSERT_EQ(rig.count(Kind::Departed, Br218), 1) << rig.eventLog();
    ASSERT_TRUE(rig.automation->dispatcher().reservations().turnoutOwner(2).has_value());
    otherControllerSends(rig.rig.station, cs2::AccessorySwitch{cs2::LocId(0x3001), 0, 1, std::nullopt});
    ASSERT_TRUE(waitFor([&] { return rig.railway->accessory(2)->position() == 0; }));
    rig.run(std::chrono::milliseconds(500));
    EXPECT_EQ(rig.count(Kind::Fault, Br218), 1) << rig.eventLog();
    EXPECT_EQ(rig.automation->dispatcher().train(Br218)->state, TrainState::Fault);
    EXPECT_EQ(rig.rig.station.loco(Br218)->speed, 0);
    rig.run(std::chrono::seconds(5));
    EXPECT_EQ(rig.movement->accidents().total(), 0) << rig.accidents.front();
}

// The automation takes the BR 218 to be a third as fast as it is (a speed measured wrong): in a block with
// one contact it stops it far too late, the train runs on into a block not reserved for it, and the track
// power goes off at once.
TEST(Automation, AnOverrunSwitchesTheTrackPowerOff) {
    AutomationRig rig;
    automation::Dispatcher::Options options = AutomationRig::fastOptions();
    options.speeds.topSpeedMmPerSecond = 150;
    ASSERT_TRUE(rig.start({{Br218, 1, End::B}}, options));
    rig.startAutomation();
    for (int i = 0; i < 1200 && rig.count(Kind::Overrun, Br218) == 0; ++i)
        rig.run(AutomationRig::Step);
    EXPECT_EQ(rig.count(Kind::Overrun, Br218), 1) << rig.eventLog();
    EXPECT_TRUE(waitFor([&] { return rig.rig.station.power() == sim::SimulatedStation::Power::Stopped; }));
    EXPECT_TRUE(rig.automation->dispatcher().paused());
}

// Mixed operation: another controller on the bus drives the running BR 218 (as a person on a second
// Central Station or a phone would). It is manual at once: the automation sends it nothing, its blocks
// stay reserved while the ICE runs on, nobody collides. Handed back where it stands, it runs on by itself.
TEST(Automation, AnotherControllerDrivingAnAutomaticTrainMakesItManualUntilHandedBack) {
    AutomationRig rig;
    ASSERT_TRUE(rig.start({{Br218, 1, End::B}, {Ice, 4, End::B}}));
    rig.startAutomation();
    const automation::Dispatcher& dispatcher = rig.automation->dispatcher();
    for (int i = 0; i < 200 && dispatcher.train(Br218)->state != TrainState::Running; ++i)
        rig.run(AutomationRig::Step);
    ASSERT_EQ(dispatcher.train(Br218)->state, TrainState::Running) << rig.eventLog();
    const int destination = *dispatcher.train(Br218)->destination;
    otherControllerSends(rig.rig.station, cs2::LocoSpeed{cs2::LocId(Br218), 300});
    ASSERT_TRUE(waitFor([&] { return rig.railway->locomotive(Br218)->speed() == 300; }));
    rig.settle();
    EXPECT_EQ(dispatcher.train(Br218)->mode, automation::TrainMode::Manual);
    EXPECT_EQ(rig.count(Kind::Manual, Br218), 1) << rig.eventLog();
    for (int i = 0; i < 400 && rig.movement->position(Br218)->block != destination; ++i)
        rig.run(AutomationRig::Step);
    ASSERT_EQ(rig.movement->position(Br218)->block, destination);
    otherControllerSends(rig.rig.station, cs2::LocoSpeed{cs2::LocId(Br218), 0});
    ASSERT_TRUE(waitFor([&] { return rig.railway->locomotive(Br218)->speed() == 0; }));
    const int iceMoves = rig.count(Kind::Entered, Ice);
    rig.run(std::chrono::seconds(30));
    EXPECT_EQ(rig.rig.station.loco(Br218)->speed, 0) << "the automation does not drive it";
    EXPECT_EQ(dispatcher.reservations().blockOwner(destination), Br218);
    EXPECT_GT(rig.count(Kind::Entered, Ice), iceMoves) << rig.eventLog();
    const int arrived = rig.count(Kind::Arrived, Br218);
    rig.automation->handBack(Br218);
    rig.run(std::chrono::seconds(60));
    EXPECT_EQ(dispatcher.train(Br218)->mode, automation::TrainMode::Automatic);
    EXPECT_GT(rig.count(Kind::Arrived, Br218), arrived) << rig.eventLog();
    EXPECT_EQ(dispatcher.faults(), 0) << rig.eventLog();
    EXPECT_EQ(rig.movement->accidents().total(), 0) << rig.accidents.front();
}

// Another controller stops the BR 218 the moment the station confirmed its departure: the program hears
// both answers (500, then 0) in one read. The 0 is not the automation's (it sent 500 last, and no command
// of its failed), so the train is manual and the automation does not drive it on.
TEST(Automation, AStopByAnotherControllerHeardTogetherWithTheDepartureMakesTheTrainManual) {
    AutomationRig rig;
    ASSERT_TRUE(rig.start({{Br218, 1, End::B}}));
    bool stopped = false;
    QObject::connect(&rig.rig.station, &sim::SimulatedStation::framesEmitted,
                     [&](const std::vector<can::CanFrame>& frames) {
                         for (const can::CanFrame& frame : frames) {
                             const cs2::DecodeResult decoded = cs2::decode(frame);
                             const auto* speed =
                                 decoded ? std::get_if<cs2::LocoSpeed>(&decoded->body) : nullptr;
                             if (!stopped && speed && decoded->response && speed->speed.value_or(0) > 0) {
                                 stopped = true;
                                 otherControllerSends(rig.rig.station, cs2::LocoSpeed{cs2::LocId(Br218), 0});
                             }
                         }
                     });
    rig.startAutomation();
    for (int i = 0; i < 200 && !stopped; ++i)
        rig.run(AutomationRig::Step);
    ASSERT_TRUE(stopped) << rig.eventLog();
    rig.run(std::chrono::seconds(1));
    EXPECT_EQ(rig.automation->dispatcher().train(Br218)->mode, automation::TrainMode::Manual)
        << rig.eventLog();
    EXPECT_EQ(rig.count(Kind::Manual, Br218), 1) << rig.eventLog();
    rig.run(std::chrono::seconds(20));
    EXPECT_EQ(rig.rig.station.loco(Br218)->speed, 0) << "the automation does not drive it on";
    EXPECT_EQ(rig.count(Kind::Lost, Br218), 0) << rig.eventLog();
    EXPECT_EQ(rig.movement->accidents().total(), 0);
}

// The desk's throttle, an MS1 (RailwayHandhelds) and an OpenRailCAN throttle (RailwayThrottles) all command
// through the railway: a speed set there makes the automatic ICE manual, and nothing more is sent to it.
TEST(Automation, AThrottleOfThisProgramOnAnAutomaticTrainMakesItManual) {
    AutomationRig rig;
    ASSERT_TRUE(rig.start({{Ice, 4, End::B}}));
    rig.startAutomation();
    const automation::Dispatcher& dispatcher = rig.automation->dispatcher();
    for (int i = 0; i < 200 && dispatcher.train(Ice)->state != TrainState::Running; ++i)
        rig.run(AutomationRig::Step);
    ASSERT_EQ(dispatcher.train(Ice)->state, TrainState::Running) << rig.eventLog();
    rig.railway->setSpeed(Ice, 0);
    rig.settle();
    EXPECT_EQ(dispatcher.train(Ice)->mode, automation::TrainMode::Manual);
    EXPECT_EQ(rig.count(Kind::Manual, Ice), 1) << rig.eventLog();
    rig.run(std::chrono::seconds(20));
    EXPECT_EQ(rig.rig.station.loco(Ice)->speed, 0);
    EXPECT_EQ(rig.count(Kind::Departed, Ice), 1) << rig.eventLog();
    EXPECT_EQ(rig.movement->accidents().total(), 0);
}

// Schedules on the simulator: the BR 218 runs Gleis 1 (8 s) - Block 3 (5 s) round and round while the ICE and
// the V 100 run wherever they find room (so its way is rarely free all the way: it goes on block by block
// towards its stop); five simulated minutes without accident, every stop's dwell kept to within a second.
TEST(Automation, ALoopScheduleRunsForSimulatedMinutesAndKeepsItsDwells) {
    AutomationRig rig;
    ASSERT_TRUE(rig.start(demoTrains()));
    const auto schedules = automation::parseSchedules(R"({"trains": [{"loc": "mfx:1", "loop": true,
        "stops": [{"block": "Gleis 1", "dwell": 8}, {"block": "Block 3", "dwell": 5}]}]})");
    ASSERT_TRUE(bool(schedules)) << schedules.error();
    ASSERT_EQ(rig.automation->setSchedule(Br218, schedules->at(Br218)), std::nullopt);
    rig.startAutomation();
    rig.run(std::chrono::minutes(5));
    const automation::Dispatcher& dispatcher = rig.automation->dispatcher();
    int atGleis1 = 0, atBlock3 = 0;
    for (const AutomationEvent& event : rig.events)
        if (event.kind == Kind::Arrived && event.locId == Br218 &&
            event.text.find(" of 2, for ") != std::string::npos) {
            atGleis1 += rig.graph->block(event.block).name == "Gleis 1";
            atBlock3 += rig.graph->block(event.block).name == "Block 3";
        }
    EXPECT_GE(atGleis1, 3) << rig.eventLog();
    EXPECT_GE(atBlock3, 3) << rig.eventLog();
    EXPECT_LE(dispatcher.worstDwellError(), 1000);
    EXPECT_EQ(dispatcher.faults(), 0) << rig.eventLog();
    EXPECT_EQ(rig.movement->accidents().total(), 0) << rig.accidents.front();
}

// Turning on the simulator: the push-pull BR 218 runs Gleis 1 - Abstellgleis round and round. The siding
// ends at buffer stops, so it turns there (any train would); back on Gleis 1 it faces the loop, which never
// leads into the siding, so it turns again, as only a push-pull train may. Three simulated minutes, no
// buffer stop hit, no accident.
TEST(Automation, APushPullTrainTurnsAtTheSidingAndOnGleis1WithoutAccident) {
    AutomationRig rig;
    ASSERT_TRUE(rig.start({{Br218, 1, End::B}}));
    const auto schedules = automation::parseSchedules(R"({"trains": [{"loc": "mfx:1", "loop": true,
        "pushPull": true,
        "stops": [{"block": "Abstellgleis", "dwell": 2}, {"block": "Gleis 1", "dwell": 2}]}]})");
    ASSERT_TRUE(bool(schedules)) << schedules.error();
    ASSERT_EQ(rig.automation->setSchedule(Br218, schedules->at(Br218)), std::nullopt);
    rig.startAutomation();
    rig.run(std::chrono::minutes(3));
    int inSiding = 0;
    for (const AutomationEvent& event : rig.events)
        inSiding += event.kind == Kind::Arrived && rig.graph->block(event.block).name == "Abstellgleis";
    EXPECT_GE(inSiding, 3) << rig.eventLog();
    EXPECT_GE(rig.count(Kind::Reversed, Br218), 5) << rig.eventLog();
    EXPECT_EQ(rig.automation->dispatcher().faults(), 0) << rig.eventLog();
    EXPECT_EQ(rig.movement->accidents().total(), 0) << rig.accidents.front();
}

// Opposing trains: the demo's single line (Block 1 to Block 4, with Ausfahrt Ost and Einfahrt West) has one
// place to pass, the station's Gleis 1 and Gleis 2. The BR 218 runs round it one way, the ICE the other way.
// Five simulated minutes: no accident, no fault, and both keep moving in every minute (no deadlock).
TEST(Automation, TwoTrainsRunOppositeWaysOverTheSingleLineAndPassInTheStation) {
    AutomationRig rig;
    ASSERT_TRUE(rig.start({{Br218, 1, End::B}, {Ice, 2, End::A}}));
    rig.startAutomation();
    for (int minute = 0; minute < 5; ++minute) {
        const int br218 = rig.count(Kind::Entered, Br218), ice = rig.count(Kind::Entered, Ice);
        rig.run(std::chrono::minutes(1));
        EXPECT_GT(rig.count(Kind::Entered, Br218), br218) << "minute " << minute << "\n" << rig.eventLog();
        EXPECT_GT(rig.count(Kind::Entered, Ice), ice) << "minute " << minute << "\n" << rig.eventLog();
    }
    EXPECT_GE(rig.automation->dispatcher().blockMoves(), 40);
    EXPECT_EQ(rig.automation->dispatcher().faults(), 0) << rig.eventLog();
    EXPECT_EQ(rig.movement->accidents().total(), 0) << rig.accidents.front();
}

// The demo without W2 in magnetartikel.cs2: the railway cannot switch turnout 2 (no such article on the
// keyboard), so it is never confirmed. After three attempts the BR 218 has not moved, its way is given back
// and the fault names the turnout.
TEST(Automation, ATurnoutNeverConfirmedKeepsTheTrainAndGivesItsWayBack) {
    sim::StationLayout::Files files = sim::StationLayout::demo().files();
    std::string& accessories = files["magnetartikel.cs2"];
    const std::size_t w2 = accessories.find("artikel\n .id=2\n");
    ASSERT_NE(w2, std::string::npos);
    accessories.erase(w2, accessories.find("artikel\n .id=3\n") - w2);
    AutomationRig rig(sim::StationLayout::fromFiles(std::move(files)));
    ASSERT_TRUE(rig.start({{Br218, 1, End::B}}));
    rig.startAutomation();
    for (int i = 0; i < 400 && rig.count(Kind::Fault, Br218) == 0; ++i)
        rig.run(AutomationRig::Step);
    EXPECT_EQ(rig.count(Kind::Fault, Br218), 1) << rig.eventLog();
    EXPECT_EQ(rig.count(Kind::Departed, Br218), 0) << rig.eventLog();
    EXPECT_NE(rig.events.back().text.find("turnout 2 was not confirmed"), std::string::npos)
        << rig.eventLog();
    const automation::Reservations& reservations = rig.automation->dispatcher().reservations();
    EXPECT_EQ(reservations.blocksOf(Br218), std::vector<int>{rig.movement->position(Br218)->block});
    EXPECT_TRUE(reservations.connectionsOf(Br218).empty());
    EXPECT_EQ(rig.rig.station.loco(Br218)->speed, 0);
    EXPECT_EQ(rig.movement->accidents().total(), 0);
}

// The station goes away while the BR 218 runs: automation pauses and the train is stopped-unknown; when the
// station is back and read again, the train is told to stop (the station kept what it had: speed 500, as a
// real one keeps its trains running) and nothing else is sent (no speed, no turnout) until the user resumes.
// Then the run goes on without accident.
TEST(Automation, WhenTheStationFallsSilentNothingIsSentUntilTheUserResumes) {
    AutomationRig rig;
    ASSERT_TRUE(rig.start({{Br218, 1, End::B}, {Ice, 4, End::B}}));
    rig.startAutomation();
    for (int i = 0; i < 200 && rig.automation->dispatcher().train(Br218)->state != TrainState::Running; ++i)
        rig.run(AutomationRig::Step);
    ASSERT_EQ(rig.automation->dispatcher().train(Br218)->state, TrainState::Running) << rig.eventLog();
    rig.rig.stopServer();
    ASSERT_TRUE(waitFor([&] { return !rig.railway->isStateReported(); }));
    EXPECT_EQ(rig.automation->dispatcher().train(Br218)->state, TrainState::Unknown);
    EXPECT_TRUE(rig.automation->dispatcher().paused());
    std::vector<std::string> received;
    QObject::connect(&rig.rig.station, &sim::SimulatedStation::frameReceived,
                     [&](const can::CanFrame& frame) {
                         const cs2::DecodeResult decoded = cs2::decode(frame);
                         const auto* speed = decoded ? std::get_if<cs2::LocoSpeed>(&decoded->body) : nullptr;
                         if ((speed && speed->speed.value_or(0) != 0) ||
                             (decoded && std::holds_alternative<cs2::AccessorySwitch>(decoded->body)))
                             received.push_back(can::formatDocument(frame));
                     });
    ASSERT_TRUE(rig.rig.startServer());
    ASSERT_TRUE(
        waitFor([&] { return rig.rig.transport->state() == transport::Transport::State::Connected; }));
    ASSERT_TRUE(rig.readAgain());
    for (int i = 0; i < 20; ++i) {
        rig.automation->tick();
        rig.settle();
    }
    EXPECT_TRUE(received.empty()) << received.front();
    EXPECT_EQ(rig.automation->dispatcher().train(Br218)->state, TrainState::Unknown);
    EXPECT_EQ(rig.rig.station.loco(Br218)->speed, 0) << "told to stop when the station is back";
    EXPECT_EQ(rig.rig.station.loco(Ice)->speed, 0);
    const int arrived = rig.count(Kind::Arrived, Br218);
    rig.run(std::chrono::seconds(5));
    EXPECT_TRUE(received.empty()) << received.front();
    EXPECT_EQ(rig.count(Kind::Arrived, Br218), arrived) << "nothing moves until resumed";
    rig.automation->resume();
    rig.settle();
    EXPECT_EQ(rig.rig.station.loco(Br218)->speed, 0);
    rig.run(std::chrono::seconds(60));
    EXPECT_EQ(rig.movement->accidents().total(), 0) << rig.accidents.front();
    EXPECT_GE(rig.count(Kind::Arrived, Br218), 1) << rig.eventLog();
}

// karben.cs2 of the corpus has three blocks and no way between them (turnouts and open ends only): the train
// placed on 602 waits for a way, and nothing is switched, driven or derailed.
TEST(Automation, OnKarbenWithoutAnyWayBetweenBlocksTheTrainWaitsAndNothingHappens) {
    cs2config::Diagnostics diagnostics("karben");
    AutomationRig rig(sim::StationLayout::load(std::string(STELLWERK_SHARED_DIR) +
                                                   "/corpus/GBert__railroad/can2udp/files/maerklin/config",
                                               diagnostics));
    constexpr std::uint32_t Train602 = 0x000b;
    ASSERT_TRUE(rig.start({{Train602, 102, End::A}}));
    ASSERT_EQ(rig.graph->blocks().size(), 3u);
    rig.startAutomation();
    rig.run(std::chrono::seconds(30));
    EXPECT_EQ(rig.count(Kind::Placed, Train602), 1);
    EXPECT_EQ(rig.count(Kind::Reserved), 0) << rig.eventLog();
    EXPECT_EQ(rig.automation->dispatcher().train(Train602)->state, TrainState::Waiting);
    EXPECT_EQ(rig.rig.station.loco(Train602)->speed, 0);
    EXPECT_EQ(rig.movement->accidents().total(), 0);
}

} // namespace
} // namespace stellwerk::e2e
