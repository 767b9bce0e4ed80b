// Schedules on the demo's graph alone: the file read and written again, a train run to its stops in turn
// with each stop's dwell on the dispatcher's clock, and a schedule resumed where a run left it.
#include "automation/Schedule.h"

#include "AutomationTestSupport.h"
#include "automation/Dispatcher.h"

#include <algorithm>

namespace stellwerk::automation {
namespace {

using namespace test;
using Kind = AutomationEvent::Kind;
using trackgraph::End;

constexpr std::uint32_t Loco = 0x4001;

constexpr const char* TwoStops = R"({"trains": [{"loc": "mfx:1", "loop": true, "next": 1,
    "stops": [{"block": "Block 3", "dwell": 4.5}, {"block": "Gleis 1", "dwell": 6}]}]})";

TEST(ScheduleFile, IsReadAndWrittenAgainWithWhereTheTrainIsInIt) {
    const auto read = parseSchedules(TwoStops);
    ASSERT_TRUE(bool(read)) << read.error();
    ASSERT_EQ(read->size(), 1u);
    const Schedule& schedule = read->at(Loco);
    EXPECT_TRUE(schedule.loop);
    EXPECT_EQ(schedule.next, 1u);
    ASSERT_EQ(schedule.stops.size(), 2u);
    EXPECT_EQ(schedule.stops[0].block, "Block 3");
    EXPECT_EQ(schedule.stops[0].dwellMs, 4500);
    const auto again = parseSchedules(schedulesJson(*read));
    ASSERT_TRUE(bool(again)) << again.error();
    EXPECT_EQ(again->at(Loco).stops[1].block, "Gleis 1");
    EXPECT_EQ(again->at(Loco).stops[1].dwellMs, 6000);
    EXPECT_EQ(again->at(Loco).next, 1u);
}

TEST(ScheduleFile, SaysWhatIsWrong) {
    EXPECT_FALSE(bool(parseSchedules("[1, 2")));
    EXPECT_NE(
        parseSchedules(R"({"trains": [{"loc": "mfx:1", "stops": []}]})").error().find("at least one stop"),
        std::string::npos);
    EXPECT_NE(parseSchedules(R"({"trains": [{"loc": "mfx:1", "stops": [{"block": "A", "dwell": -1}]}]})")
                  .error()
                  .find("not a number of seconds"),
              std::string::npos);
}

TEST(ScheduleFile, AStopInABlockTheTrackPlanDoesNotHaveIsRefused) {
    Dispatcher dispatcher{demo()};
    ASSERT_EQ(dispatcher.place(Loco, "BR 218", 200, 1, End::B), std::nullopt);
    Schedule schedule{{{"Gleis 9", 1000, 0}}, false, 0};
    const auto problem = dispatcher.setSchedule(Loco, schedule);
    ASSERT_TRUE(problem.has_value());
    EXPECT_NE(problem->find("Gleis 9"), std::string::npos);
}

// The BR 218 on Gleis 1 with the schedule above, resumed at its second stop (Gleis 1, where it stands): it
// stands 6 s, runs to Block 3 (further than any block it would choose itself), stands 4.5 s there, and
// departs within a second of each dwell's end.
class ScheduleRun : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_EQ(dispatcher.place(Loco, "BR 218", 200, 1, End::B), std::nullopt);
        ASSERT_EQ(dispatcher.setSchedule(Loco, parseSchedules(TwoStops)->at(Loco)), std::nullopt);
        dispatcher.occupancyRead({contact(1)});
        dispatcher.setMode(Loco, TrainMode::Automatic, 0);
    }
    // Every turnout switched is confirmed at once; departures noted.
    void runTo(Millis until) {
        for (; now <= until; now += 50) {
            dispatcher.tick(now);
            for (const DriveCommand& command : dispatcher.takeCommands()) {
                if (command.kind == DriveCommand::Kind::Switch)
                    dispatcher.turnoutSwitched(command.article, command.position, true, now);
                if (command.kind == DriveCommand::Kind::Speed && command.speed > 0 && !running)
                    departures.push_back(now);
                if (command.kind == DriveCommand::Kind::Speed)
                    running = command.speed > 0;
            }
            for (const AutomationEvent& event : dispatcher.takeEvents())
                events.push_back(event);
        }
    }

    Dispatcher dispatcher{demo()};
    Millis now = 0;
    bool running = false;
    std::vector<Millis> departures;
    std::vector<AutomationEvent> events;
};

TEST_F(ScheduleRun, TheTrainStandsItsDwellAndRunsToItsNextStop) {
    runTo(5900);
    EXPECT_TRUE(departures.empty()) << "it stands 6 s at Gleis 1";
    EXPECT_EQ(dispatcher.reservations().blockOwner(Block3), Loco) << "the way is set before the dwell ends";
    runTo(7000);
    ASSERT_EQ(departures.size(), 1u);
    EXPECT_LE(departures[0] - 6000, 1000);
    EXPECT_EQ(dispatcher.train(Loco)->destination, Block3);
    EXPECT_EQ(dispatcher.train(Loco)->schedule->next, 0u);
}

TEST_F(ScheduleRun, ATrainWhoseStopIsNotReachableWaitsForIt) {
    dispatcher.occupancyRead({contact(1), contact(8)}); // a ghost in Ausfahrt Ost, the only way out
    runTo(20000);
    EXPECT_TRUE(departures.empty());
    EXPECT_EQ(dispatcher.train(Loco)->state, TrainState::Waiting);
    dispatcher.contactChanged(contact(8), false, now);
    runTo(21000);
    EXPECT_EQ(departures.size(), 1u);
    EXPECT_EQ(dispatcher.train(Loco)->destination, Block3);
}

// A ghost in Block 2 on the way to Block 3: the train goes as far as is free to a block it may stop in:
// Ausfahrt Ost (Block 1 is free, but could not be left forwards with the ghost ahead of it).
TEST_F(ScheduleRun, ATrainGoesAsFarTowardsItsStopAsIsFree) {
    dispatcher.occupancyRead({contact(1), contact(4)});
    runTo(7000);
    ASSERT_EQ(departures.size(), 1u);
    EXPECT_EQ(dispatcher.train(Loco)->destination, AusfahrtOst);
    EXPECT_EQ(dispatcher.reservations().blockOwner(Block1), 0u);
}

} // namespace
} // namespace stellwerk::automation
