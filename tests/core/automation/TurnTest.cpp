// Changing direction on the demo's graph alone: the siding "Abstellgleis" ends at buffer stops (no way leads
// on from its end b), so any train turns there; elsewhere only a push-pull train turns, and only when no
// way leads on forwards.
#include "AutomationTestSupport.h"
#include "automation/Dispatcher.h"

#include <algorithm>

namespace stellwerk::automation {
namespace {

using namespace test;
using Kind = AutomationEvent::Kind;
using trackgraph::End;

constexpr std::uint32_t TurningLoco = 0x4001;

class TurnTest : public ::testing::Test {
protected:
    void start(std::int64_t contactNumber, End towards, Schedule schedule) {
        ASSERT_EQ(dispatcher.place(TurningLoco, "BR 218", 200, contactNumber, towards), std::nullopt);
        ASSERT_EQ(dispatcher.setSchedule(TurningLoco, std::move(schedule)), std::nullopt);
        dispatcher.occupancyRead({contact(contactNumber)});
        dispatcher.setMode(TurningLoco, TrainMode::Automatic, now);
    }
    // Every turnout switched is confirmed at once.
    void runTo(Millis until) {
        for (; now <= until; now += 50) {
            dispatcher.tick(now);
            for (const DriveCommand& command : dispatcher.takeCommands()) {
                if (command.kind == DriveCommand::Kind::Switch)
                    dispatcher.turnoutSwitched(command.article, command.position, true, now);
                commands.push_back(command);
            }
            for (const AutomationEvent& event : dispatcher.takeEvents())
                events.push_back(event);
        }
    }
    void contactTo(std::int64_t number, bool occupied) {
        dispatcher.contactChanged(contact(number), occupied, now);
        runTo(now);
    }
    int count(Kind kind) const {
        return int(std::count_if(events.begin(), events.end(),
                                 [kind](const AutomationEvent& e) { return e.kind == kind; }));
    }
    std::string log() const {
        std::string text;
        for (const AutomationEvent& event : events)
            text += std::string(eventKindName(event.kind)) + ": " + event.text + "\n";
        return text;
    }
    bool reversed() const {
        return std::find(commands.begin(), commands.end(), DriveCommand::reverse(TurningLoco)) !=
               commands.end();
    }

    Dispatcher dispatcher{demo()};
    Millis now = 0;
    std::vector<DriveCommand> commands;
    std::vector<AutomationEvent> events;
};

// Gleis 1 -> Abstellgleis, then Gleis 2: the only way to Gleis 2 from the siding is back the way it came.
TEST_F(TurnTest, ATrainTurnsAtATerminusAndRunsOutTheWayItCame) {
    start(1, End::B, Schedule{{{"Abstellgleis", 2000, 0}, {"Gleis 2", 2000, 0}}, false, 0});
    runTo(1000);
    ASSERT_EQ(dispatcher.train(TurningLoco)->destination, Abstellgleis);
    contactTo(8, true); // Ausfahrt Ost
    contactTo(9, true); // Abstellgleis
    contactTo(1, false);
    contactTo(8, false);
    runTo(now + 10000); // to its stop by the distance, and the dwell
    EXPECT_EQ(count(Kind::Reversed), 1) << log();
    EXPECT_TRUE(reversed());
    EXPECT_EQ(dispatcher.tracking().body(TurningLoco)->towards, End::A);
    EXPECT_EQ(dispatcher.train(TurningLoco)->destination, Gleis2);
    EXPECT_EQ(dispatcher.reservations().blockOwner(AusfahrtOst), TurningLoco);
    EXPECT_EQ(dispatcher.reservations().blockOwner(Gleis2), TurningLoco);
}

// On Block 2 facing a, to Block 1 right ahead: push-pull or not, a train with a way forwards does not turn.
TEST_F(TurnTest, APushPullTrainWithAWayForwardsDoesNotTurn) {
    Schedule toBlock1{{{"Block 1", 1000, 0}}, false, 0};
    toBlock1.pushPull = true;
    start(4, End::A, toBlock1); // Block 2, facing Block 1: forwards
    runTo(1000);
    EXPECT_FALSE(reversed());
    EXPECT_EQ(dispatcher.train(TurningLoco)->destination, Block1);
}

TEST_F(TurnTest, APushPullTrainTurnsWhenItsStopLiesOnlyBehindIt) {
    // Gleis 1 facing a leads round the loop to Ausfahrt Ost facing a: never into the siding. Push-pull, it
    // turns; not push-pull, it waits.
    Schedule toSiding{{{"Abstellgleis", 1000, 0}}, false, 0};
    start(1, End::A, toSiding);
    runTo(3000);
    EXPECT_FALSE(reversed());
    EXPECT_EQ(dispatcher.train(TurningLoco)->state, TrainState::Waiting);
    dispatcher.setPushPull(TurningLoco, true);
    runTo(4000);
    EXPECT_TRUE(reversed());
    EXPECT_EQ(dispatcher.tracking().body(TurningLoco)->towards, End::B);
    EXPECT_EQ(dispatcher.train(TurningLoco)->destination, Abstellgleis);
}

} // namespace
} // namespace stellwerk::automation
