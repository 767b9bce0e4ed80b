// What the desktop's operation asks of the Dispatcher beyond the CLI's run: a train placed in a block by its
// id, taken off again with everything it held, a schedule taken away, and "stop all at their next stop"
// (a standing train manual at once, its way given back; a running one once it has arrived).
#include "AutomationTestSupport.h"
#include "automation/Dispatcher.h"

namespace stellwerk::automation {
namespace {

using namespace test;
using trackgraph::End;

constexpr std::uint32_t Loco = 0x4001;

TEST(DeskOperation, APlacedTrainIsTakenOffWithEverythingItHeld) {
    Dispatcher dispatcher{demo()};
    ASSERT_EQ(dispatcher.placeInBlock(Loco, "BR 218", 200, Gleis1, End::B), std::nullopt);
    EXPECT_EQ(dispatcher.tracking().body(Loco)->frontBlock, Gleis1);
    EXPECT_EQ(dispatcher.reservations().blockOwner(Gleis1), Loco);
    EXPECT_NE(dispatcher.placeInBlock(0x4002, "ICE", 200, Gleis1, End::B), std::nullopt); // taken
    EXPECT_NE(dispatcher.placeInBlock(0x4002, "ICE", 200, 99, End::B), std::nullopt);     // no such block
    dispatcher.remove(Loco);
    EXPECT_EQ(dispatcher.train(Loco), nullptr);
    EXPECT_EQ(dispatcher.tracking().body(Loco), nullptr);
    EXPECT_EQ(dispatcher.reservations().blockOwner(Gleis1), 0u);
    EXPECT_EQ(dispatcher.placeInBlock(0x4002, "ICE", 200, Gleis1, End::B), std::nullopt);
}

TEST(DeskOperation, AScheduleWithoutStopsTakesTheScheduleAway) {
    Dispatcher dispatcher{demo()};
    ASSERT_EQ(dispatcher.placeInBlock(Loco, "BR 218", 200, Gleis1, End::B), std::nullopt);
    Schedule schedule;
    schedule.stops = {{"Gleis 2", 1000, 0}};
    ASSERT_EQ(dispatcher.setSchedule(Loco, schedule), std::nullopt);
    ASSERT_TRUE(dispatcher.train(Loco)->schedule.has_value());
    ASSERT_EQ(dispatcher.setSchedule(Loco, Schedule{}), std::nullopt);
    EXPECT_FALSE(dispatcher.train(Loco)->schedule.has_value());
}

TEST(DeskOperation, StopAtNextStopMakesAStandingTrainManualAndGivesItsWayBack) {
    Dispatcher dispatcher{demo()};
    ASSERT_EQ(dispatcher.placeInBlock(Loco, "BR 218", 200, Gleis1, End::B), std::nullopt);
    dispatcher.occupancyRead({contact(1)});
    dispatcher.setMode(Loco, TrainMode::Automatic, 0);
    dispatcher.tick(0); // its way is reserved, its turnouts are being set
    ASSERT_EQ(dispatcher.train(Loco)->state, TrainState::SettingWay);
    const int destination = *dispatcher.train(Loco)->destination;
    ASSERT_EQ(dispatcher.reservations().blockOwner(destination), Loco);
    dispatcher.takeCommands();
    dispatcher.stopAtNextStop(10);
    EXPECT_EQ(dispatcher.train(Loco)->mode, TrainMode::Manual);
    EXPECT_EQ(dispatcher.train(Loco)->state, TrainState::Stopped);
    EXPECT_EQ(dispatcher.reservations().blockOwner(destination), 0u);
    EXPECT_EQ(dispatcher.reservations().blockOwner(Gleis1), Loco);
    const std::vector<DriveCommand> commands = dispatcher.takeCommands();
    ASSERT_FALSE(commands.empty());
    EXPECT_EQ(commands.back(), DriveCommand::speedOf(Loco, 0));
    // Confirmed turnouts and time do not start it again.
    dispatcher.turnoutSwitched(2, 1, true, 20);
    dispatcher.turnoutSwitched(3, 1, true, 20);
    dispatcher.tick(5000);
    for (const DriveCommand& command : dispatcher.takeCommands())
        EXPECT_FALSE(command.kind == DriveCommand::Kind::Speed && command.speed > 0);
}

} // namespace
} // namespace stellwerk::automation
