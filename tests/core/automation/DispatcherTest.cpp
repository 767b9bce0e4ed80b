// The Dispatcher on the demo's graph alone, told contacts and turnout answers as the railway would: a train
// departs only when every turnout of its way is confirmed; a turnout never confirmed gives the way back; the
// track behind is given back block by block; ghosts; STOP and the station's silence stop everything until
// the user resumes.
#include "automation/Dispatcher.h"

#include "AutomationTestSupport.h"

#include <algorithm>

namespace stellwerk::automation {
namespace {

using namespace test;
using Kind = AutomationEvent::Kind;
using trackgraph::End;

constexpr std::uint32_t DispatchedLoco = 0x4001;

// BR 218 on Gleis 1 (contact 1) facing b, automatic, with its first way reserved (turnouts 2 and 3 straight).
class DispatcherTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_EQ(dispatcher.place(DispatchedLoco, "BR 218", 200, 1, End::B), std::nullopt);
        dispatcher.occupancyRead({contact(1)});
        dispatcher.setMode(DispatchedLoco, TrainMode::Automatic, 0);
        dispatcher.tick(0);
        remember();
    }
    void remember() {
        for (const DriveCommand& command : dispatcher.takeCommands())
            commands.push_back(command);
        for (const AutomationEvent& event : dispatcher.takeEvents())
            events.push_back(event);
    }
    bool sentSpeedAbove(int speed) const {
        return std::any_of(commands.begin(), commands.end(), [speed](const DriveCommand& command) {
            return command.kind == DriveCommand::Kind::Speed && command.speed > speed;
        });
    }
    int count(Kind kind) const {
        return int(std::count_if(events.begin(), events.end(),
                                 [kind](const AutomationEvent& e) { return e.kind == kind; }));
    }
    void confirmTurnouts(Millis now) {
        dispatcher.turnoutSwitched(2, 1, true, now);
        dispatcher.turnoutSwitched(3, 1, true, now);
        dispatcher.tick(now + dispatcher.options().settle);
        remember();
    }

    Dispatcher dispatcher{demo()};
    std::vector<DriveCommand> commands;
    std::vector<AutomationEvent> events;
};

TEST_F(DispatcherTest, ATrainDepartsOnlyWhenEveryTurnoutOfItsWayIsConfirmed) {
    EXPECT_EQ(commands,
              (std::vector<DriveCommand>{DriveCommand::speedOf(DispatchedLoco, 0),
                                         DriveCommand::switching(2, 1), DriveCommand::switching(3, 1)}));
    EXPECT_EQ(dispatcher.reservations().blockOwner(AusfahrtOst), DispatchedLoco);
    EXPECT_EQ(dispatcher.reservations().blockOwner(Block1), DispatchedLoco);
    dispatcher.turnoutSwitched(2, 1, true, 100);
    dispatcher.tick(2000);
    remember();
    EXPECT_FALSE(sentSpeedAbove(0));
    dispatcher.turnoutSwitched(3, 1, true, 2000);
    dispatcher.tick(2000 + dispatcher.options().settle - 1);
    remember();
    EXPECT_FALSE(sentSpeedAbove(0)) << "the turnout still moves";
    dispatcher.tick(2000 + dispatcher.options().settle);
    remember();
    EXPECT_EQ(commands.back(), DriveCommand::speedOf(DispatchedLoco, dispatcher.options().speeds.travel));
    EXPECT_EQ(dispatcher.train(DispatchedLoco)->state, TrainState::Running);
}

TEST_F(DispatcherTest, ATurnoutNeverConfirmedGivesTheWayBackWithoutDeparting) {
    dispatcher.turnoutSwitched(3, 1, true, 100);
    for (Millis now = 0; now <= 4 * dispatcher.options().switchTimeout; now += 500) {
        dispatcher.turnoutSwitched(2, 1, false, now);
        dispatcher.tick(now);
        remember();
        if (dispatcher.train(DispatchedLoco)->state == TrainState::Fault)
            break;
    }
    EXPECT_EQ(dispatcher.train(DispatchedLoco)->state, TrainState::Fault);
    EXPECT_EQ(count(Kind::Fault), 1);
    EXPECT_EQ(std::count(commands.begin(), commands.end(), DriveCommand::switching(2, 1)),
              dispatcher.options().switchAttempts);
    EXPECT_FALSE(sentSpeedAbove(0));
    EXPECT_EQ(dispatcher.reservations().blocksOf(DispatchedLoco), std::vector<int>{Gleis1});
    EXPECT_TRUE(dispatcher.reservations().connectionsOf(DispatchedLoco).empty());
}

TEST_F(DispatcherTest, TheTrackBehindIsGivenBackBlockByBlockOnceTheTrainHasLeftIt) {
    confirmTurnouts(100);
    dispatcher.contactChanged(contact(8), true, 1000); // the front in Ausfahrt Ost
    remember();
    EXPECT_EQ(count(Kind::Entered), 1);
    EXPECT_EQ(dispatcher.reservations().blockOwner(Gleis1), DispatchedLoco)
        << "its contact is still occupied";
    dispatcher.contactChanged(contact(3), true, 2000); // the front in Block 1
    dispatcher.contactChanged(contact(1), false, 2100);
    remember();
    EXPECT_EQ(dispatcher.reservations().blockOwner(Gleis1), 0u);
    EXPECT_EQ(dispatcher.reservations().blockOwner(AusfahrtOst), DispatchedLoco)
        << "contact 8 is still occupied";
    dispatcher.contactChanged(contact(8), false, 2500);
    remember();
    EXPECT_EQ(dispatcher.reservations().blockOwner(AusfahrtOst), 0u);
    EXPECT_EQ(dispatcher.reservations().blockOwner(Block1), DispatchedLoco);
    EXPECT_EQ(count(Kind::Released), 2);
    EXPECT_EQ(dispatcher.blockMoves(), 2);
}

TEST_F(DispatcherTest, AGhostOnTheReservedWayStopsTheTrainAndAGhostElsewhereIsOnlyShown) {
    confirmTurnouts(100);
    dispatcher.contactChanged(contact(5), true, 1000); // Block 3: nobody can be there
    remember();
    EXPECT_EQ(count(Kind::Ghost), 1);
    EXPECT_TRUE(dispatcher.tracking().isGhost(Block3));
    EXPECT_EQ(dispatcher.train(DispatchedLoco)->state, TrainState::Running);
    dispatcher.contactChanged(contact(3), true,
                              1100); // Block 1, reserved for the BR 218, before it got there
    remember();
    EXPECT_EQ(dispatcher.train(DispatchedLoco)->state, TrainState::Fault);
    EXPECT_EQ(commands.back(), DriveCommand::speedOf(DispatchedLoco, 0));
}

TEST_F(DispatcherTest, AfterStopNothingStartsUntilTheUserResumes) {
    dispatcher.halt("STOP");
    remember();
    EXPECT_EQ(commands.back(), DriveCommand::speedOf(DispatchedLoco, 0));
    commands.clear();
    confirmTurnouts(100);
    dispatcher.tick(60000);
    remember();
    EXPECT_TRUE(commands.empty());
    dispatcher.resume(60000);
    dispatcher.tick(60000);
    remember();
    EXPECT_EQ(commands,
              (std::vector<DriveCommand>{DriveCommand::speedOf(DispatchedLoco, 0),
                                         DriveCommand::switching(2, 1), DriveCommand::switching(3, 1)}));
}

TEST_F(DispatcherTest, WhileTheStationIsSilentTheTrainIsUnknownAndStaysStoppedWhenItReturns) {
    confirmTurnouts(100);
    ASSERT_EQ(dispatcher.train(DispatchedLoco)->state, TrainState::Running);
    commands.clear();
    dispatcher.stationLost();
    dispatcher.tick(5000);
    remember();
    EXPECT_EQ(dispatcher.train(DispatchedLoco)->state, TrainState::Unknown);
    EXPECT_TRUE(commands.empty()) << "nothing is sent to a silent station";
    EXPECT_NE(events.back().text.find("BR 218 is stopped-unknown"), std::string::npos) << events.back().text;
    dispatcher.occupancyRead({contact(1)}); // back: still on Gleis 1
    dispatcher.stationBack();
    dispatcher.tick(6000);
    remember();
    EXPECT_EQ(dispatcher.train(DispatchedLoco)->state, TrainState::Unknown);
    EXPECT_EQ(commands, std::vector<DriveCommand>{DriveCommand::speedOf(DispatchedLoco, 0)})
        << "told to stop (the station may have kept it running), nothing replayed";
    EXPECT_NE(events.back().text.find("stays until automation is resumed"), std::string::npos);
    commands.clear();
    dispatcher.resume(7000);
    remember();
    EXPECT_EQ(commands, std::vector<DriveCommand>{DriveCommand::speedOf(DispatchedLoco, 0)});
    EXPECT_EQ(dispatcher.train(DispatchedLoco)->state, TrainState::Waiting);
    EXPECT_EQ(dispatcher.reservations().blocksOf(DispatchedLoco), std::vector<int>{Gleis1});
}

// The BR 218 stands in Block 1 past its only contact (it stopped by the distance), unseen: when the station
// returns, it is still where it stood.
TEST_F(DispatcherTest, ATrainThatStoodUnseenIsWhereItStoodWhenTheStationReturns) {
    confirmTurnouts(100);
    dispatcher.contactChanged(contact(8), true, 1000);
    dispatcher.contactChanged(contact(3), true, 2000);
    dispatcher.contactChanged(contact(1), false, 2100);
    dispatcher.contactChanged(contact(8), false, 2200);
    dispatcher.tick(60000);                              // stopped by the distance in Block 1
    dispatcher.contactChanged(contact(3), false, 61000); // its contact behind it
    remember();
    ASSERT_EQ(dispatcher.tracking().body(DispatchedLoco)->frontBlock, Block1);
    ASSERT_EQ(dispatcher.train(DispatchedLoco)->state, TrainState::Waiting) << events.back().text;
    dispatcher.stationLost();
    dispatcher.occupancyRead({});
    remember();
    EXPECT_EQ(dispatcher.train(DispatchedLoco)->state, TrainState::Unknown);
    EXPECT_EQ(count(Kind::Lost), 0);
}

TEST_F(DispatcherTest, ATrainNotSeenWhereItStoodWhenTheStationReturnsIsLost) {
    dispatcher.stationLost();
    dispatcher.occupancyRead({contact(5)});
    remember();
    EXPECT_EQ(dispatcher.train(DispatchedLoco)->state, TrainState::Lost);
    EXPECT_EQ(count(Kind::Lost), 1);
    EXPECT_EQ(count(Kind::Ghost), 1);
}

TEST_F(DispatcherTest, ATrainThatDoesNotArriveInTimeIsLost) {
    confirmTurnouts(100);
    dispatcher.tick(10 * 60 * 1000);
    remember();
    EXPECT_EQ(dispatcher.train(DispatchedLoco)->state, TrainState::Lost);
    EXPECT_EQ(commands.back(), DriveCommand::speedOf(DispatchedLoco, 0));
}

// Mixed operation: a throttle takes the running BR 218; the automation sends it nothing more, its way stays
// reserved (a turnout switched on it no longer stops anything), and handed back in Block 1 it gives back the
// way it held ahead and sets out anew from there.
TEST_F(DispatcherTest, ATrainTakenByHandKeepsItsWayAndHandedBackSetsOutFromWhereItStands) {
    confirmTurnouts(100);
    ASSERT_EQ(dispatcher.train(DispatchedLoco)->state, TrainState::Running);
    commands.clear();
    dispatcher.takenByHand(DispatchedLoco, "a throttle");
    dispatcher.contactChanged(contact(8), true, 2000);
    ASSERT_TRUE(dispatcher.reservations().turnoutOwner(2).has_value());
    dispatcher.turnoutReported(2, 0, 2500);            // behind its front, under its body
    dispatcher.contactChanged(contact(3), true, 3000); // the person drives it into Block 1
    dispatcher.contactChanged(contact(1), false, 3100);
    dispatcher.contactChanged(contact(8), false, 3200);
    dispatcher.tick(60000);
    remember();
    EXPECT_EQ(dispatcher.train(DispatchedLoco)->mode, TrainMode::Manual);
    EXPECT_EQ(count(Kind::Manual), 1);
    EXPECT_EQ(count(Kind::Fault), 0);
    EXPECT_TRUE(std::none_of(commands.begin(), commands.end(), [](const DriveCommand& c) {
        return c.kind == DriveCommand::Kind::Speed;
    })) << "nothing is sent to a train driven by hand";
    EXPECT_EQ(commands,
              std::vector<DriveCommand>{DriveCommand::switching(7, dispatcher.options().signalStop)})
        << "the signal it passed shows stop behind it";
    EXPECT_EQ(dispatcher.reservations().blockOwner(Block1), DispatchedLoco);
    commands.clear();
    dispatcher.handBack(DispatchedLoco, 60000);
    dispatcher.tick(60000);
    remember();
    EXPECT_EQ(dispatcher.train(DispatchedLoco)->mode, TrainMode::Automatic);
    EXPECT_EQ(count(Kind::Automatic), 1);
    ASSERT_FALSE(commands.empty());
    EXPECT_EQ(commands.front(), DriveCommand::speedOf(DispatchedLoco, 0));
    EXPECT_EQ(dispatcher.train(DispatchedLoco)->state, TrainState::SettingWay);
    EXPECT_EQ(dispatcher.reservations().blockOwner(Block2), DispatchedLoco) << "its new way, on from Block 1";
    EXPECT_EQ(dispatcher.reservations().blockOwner(Gleis1), 0u);
}

// The signal at the start of the way (P1, keyboard 7, at the end of Gleis 1 the train faces) shows proceed
// only once every turnout is confirmed, and stop again as soon as the train has entered the next block.
TEST_F(DispatcherTest, TheSignalAtTheStartShowsProceedOnlyAtDepartureAndStopBehindTheTrain) {
    const DriveCommand proceed = DriveCommand::switching(7, dispatcher.options().signalProceed);
    const DriveCommand stop = DriveCommand::switching(7, dispatcher.options().signalStop);
    EXPECT_EQ(std::count(commands.begin(), commands.end(), proceed), 0) << "turnouts not confirmed yet";
    confirmTurnouts(100);
    ASSERT_EQ(dispatcher.train(DispatchedLoco)->state, TrainState::Running);
    const auto shown = std::find(commands.begin(), commands.end(), proceed);
    ASSERT_NE(shown, commands.end());
    EXPECT_LT(shown - commands.begin(),
              std::find(commands.begin(), commands.end(),
                        DriveCommand::speedOf(DispatchedLoco, dispatcher.options().speeds.travel)) -
                  commands.begin())
        << "proceed before the train moves";
    EXPECT_EQ(std::count(commands.begin(), commands.end(), stop), 0);
    dispatcher.contactChanged(contact(8), true, 2000); // the front in Ausfahrt Ost
    remember();
    EXPECT_EQ(std::count(commands.begin(), commands.end(), stop), 1);
    EXPECT_EQ(std::count(commands.begin(), commands.end(), proceed), 1);
}

// A train stopped by a fault before it passed its signal: the signal shows stop again at once.
TEST_F(DispatcherTest, ASignalGivenToATrainStoppedByAFaultShowsStopAgain) {
    confirmTurnouts(100);
    ASSERT_EQ(dispatcher.train(DispatchedLoco)->state, TrainState::Running);
    dispatcher.contactChanged(contact(3), true, 500); // a ghost in Block 1, on its way
    remember();
    ASSERT_EQ(dispatcher.train(DispatchedLoco)->state, TrainState::Fault);
    EXPECT_EQ(std::count(commands.begin(), commands.end(),
                         DriveCommand::switching(7, dispatcher.options().signalStop)),
              1);
}

} // namespace
} // namespace stellwerk::automation
