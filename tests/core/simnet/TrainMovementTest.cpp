// Trains that move: running locomotives occupy and release S88 contacts along the demo plan, in the
// direction they run, and follow the turnouts.

#include "sim/TrainMovement.h"

#include "SimTestSupport.h"
#include "sim/SimulatedStation.h"
#include "sim/StationLayout.h"
#include "sim/TrainTrack.h"

#include <algorithm>
#include <chrono>
#include <gtest/gtest.h>
#include <vector>

namespace stellwerk::sim {
namespace {

using namespace std::chrono_literals;
using test::ContactEvent;

constexpr std::uint32_t Br218 = 0x4001;
constexpr std::uint32_t W1 = 0x3000; // keyboard 1
constexpr std::uint32_t W3 = 0x3002; // keyboard 3
constexpr std::uint8_t Round = 0;

// The demo track with one locomotive on it, at `section`, on a station with track power on.
class TrainMovementTest : public ::testing::Test {
protected:
    void placeBr218(const char* section, int offsetMm) {
        TrainTrack track = TrainTrack::demo();
        track.placements = {{Br218, *track.find(section), offsetMm}};
        movement_ = std::make_unique<TrainMovement>(station_, std::move(track));
        movement_->start();
        movement_->stop(); // the tests move the trains themselves
        contacts_.events.clear();
    }

    // Moves in 100 ms steps for `duration` of simulated time.
    void run(std::chrono::milliseconds duration) {
        for (auto elapsed = 0ms; elapsed < duration; elapsed += 100ms)
            movement_->advance(100ms);
    }

    int section(const char* name) const { return *movement_->track().find(name); }

    SimulatedStation station_{StationLayout::demo(), {.power = SimulatedStation::Power::Running}};
    test::ContactRecorder contacts_{station_};
    std::unique_ptr<TrainMovement> movement_;
};

TEST_F(TrainMovementTest, PlacedTrainOccupiesItsSectionAtStart) {
    test::ContactRecorder recorder(station_);
    TrainTrack track = TrainTrack::demo();
    track.placements = {{Br218, *track.find("Gleis 1"), 1500}};
    TrainMovement movement(station_, std::move(track));
    movement.start();
    movement.stop();
    EXPECT_EQ(recorder.events, (std::vector<ContactEvent>{{1, true}}));
    EXPECT_TRUE(station_.contact(0, 1));
}

// What a real station cannot say and the simulator can: which train is on which contact.
TEST_F(TrainMovementTest, TellsWhichTrainComesOntoAContactAndWhenItLeaves) {
    TrainTrack track = TrainTrack::demo();
    track.placements = {{Br218, *track.find("Gleis 1"), 1500}};
    TrainMovement movement(station_, std::move(track));
    std::vector<std::pair<std::uint16_t, std::uint32_t>> told; // contact, Loc-ID
    QObject::connect(&movement, &TrainMovement::occupantChanged,
                     [&told](std::uint16_t, std::uint16_t contact, std::uint32_t locId) {
                         told.emplace_back(contact, locId);
                     });
    movement.start();
    movement.stop();
    EXPECT_EQ(told, (std::vector<std::pair<std::uint16_t, std::uint32_t>>{{1, Br218}}))
        << "placed on Gleis 1";
    EXPECT_EQ(movement.occupantOf(*movement.track().find("Gleis 1")), Br218);
    told.clear();
    station_.receive(test::speed(Br218, 1000));
    for (int step = 0; step < 20; ++step) // 2 s at 500 mm/s: into Ausfahrt Ost, clear of Gleis 1
        movement.advance(100ms);
    EXPECT_EQ(told, (std::vector<std::pair<std::uint16_t, std::uint32_t>>{{8, Br218}, {1, 0}}));
    EXPECT_EQ(movement.occupantOf(*movement.track().find("Ausfahrt Ost")), Br218);
    EXPECT_EQ(movement.occupantOf(*movement.track().find("Gleis 1")), 0u);
}

TEST_F(TrainMovementTest, RunningForwardPassesTheContactsAroundTheLoopInOrder) {
    placeBr218("Gleis 1", 1500);
    station_.receive(test::speed(Br218, 1000)); // 500 mm/s: once round the 14.4 m loop
    run(29s);
    const std::vector<ContactEvent> expected = {
        {8, true},  {1, false}, {3, true},  {8, false}, {4, true},  {3, false}, {5, true},
        {4, false}, {6, true},  {5, false}, {7, true},  {6, false}, {1, true},  {7, false},
    };
    EXPECT_EQ(contacts_.events, expected);
}

TEST_F(TrainMovementTest, EnteringSetsTheContactAndOnlyTheRearEndReleasesThePrevious) {
    placeBr218("Gleis 1", 1900);
    station_.receive(test::speed(Br218, 1000)); // 50 mm per tick; the train is 250 mm long
    run(300ms);                                 // front 50 mm into Ausfahrt Ost, rear still in Gleis 1
    EXPECT_EQ(contacts_.events, (std::vector<ContactEvent>{{8, true}}));
    EXPECT_EQ(movement_->position(Br218)->occupiedSections,
              (std::vector<int>{section("Ausfahrt Ost"), section("Gleis 1")}));
    run(300ms); // front 200 mm in: the last 50 mm of the train are still in Gleis 1
    EXPECT_EQ(contacts_.events, (std::vector<ContactEvent>{{8, true}}));
    run(100ms); // front 250 mm in: the rear end has left
    EXPECT_EQ(contacts_.events, (std::vector<ContactEvent>{{8, true}, {1, false}}));
    EXPECT_EQ(movement_->position(Br218)->occupiedSections, (std::vector<int>{section("Ausfahrt Ost")}));
}

TEST_F(TrainMovementTest, ReversedDirectionRunsTheOtherWay) {
    placeBr218("Gleis 1", 1500);
    station_.receive(test::direction(Br218, cs2::Direction::Backward));
    station_.receive(test::speed(Br218, 1000));
    run(8s);
    const std::vector<ContactEvent> expected = {{7, true}, {1, false}, {6, true}, {7, false}};
    EXPECT_EQ(contacts_.events, expected);
    EXPECT_FALSE(movement_->position(Br218)->headingAhead);
}

TEST_F(TrainMovementTest, TurningBackReturnsThroughTheSectionsItCameFrom) {
    placeBr218("Gleis 1", 1900);
    station_.receive(test::speed(Br218, 1000));
    run(1s); // front in Ausfahrt Ost, Gleis 1 released
    ASSERT_EQ(contacts_.events, (std::vector<ContactEvent>{{8, true}, {1, false}}));
    station_.receive(test::direction(Br218, cs2::Direction::Backward));
    station_.receive(test::speed(Br218, 1000));
    run(2s);
    EXPECT_EQ(contacts_.events, (std::vector<ContactEvent>{{8, true}, {1, false}, {1, true}, {8, false}}));
}

TEST_F(TrainMovementTest, SpeedZeroStopsTheTrain) {
    placeBr218("Gleis 1", 1000);
    station_.receive(test::speed(Br218, 500));
    run(1s);
    const TrainPosition moving = *movement_->position(Br218);
    EXPECT_EQ(moving.frontMm, 1250);
    station_.receive(test::speed(Br218, 0));
    run(5s);
    EXPECT_EQ(movement_->position(Br218)->frontMm, 1250);
    EXPECT_EQ(movement_->position(Br218)->section, section("Gleis 1"));
    EXPECT_TRUE(contacts_.events.empty());
}

TEST_F(TrainMovementTest, WithoutTrackPowerNothingMoves) {
    placeBr218("Gleis 1", 1000);
    station_.receive(test::speed(Br218, 1000));
    station_.receive(test::command(cs2::SystemStop{}));
    ASSERT_EQ(station_.power(), SimulatedStation::Power::Stopped);
    run(2s);
    EXPECT_EQ(movement_->position(Br218)->frontMm, 1000);
    EXPECT_EQ(movement_->trackLoad(), 0);
}

TEST_F(TrainMovementTest, TurnoutW1RoundLeadsIntoThePassingTrack) {
    placeBr218("Einfahrt West", 1000);
    station_.receive(test::switchAccessory(W1, Round));
    ASSERT_TRUE(test::waitFor([&] { return station_.accessoryPosition(W1) == Round; }));
    station_.receive(test::speed(Br218, 1000));
    run(3s);
    EXPECT_EQ(contacts_.events, (std::vector<ContactEvent>{{2, true}, {7, false}}));
    EXPECT_EQ(movement_->position(Br218)->section, section("Gleis 2"));
}

TEST_F(TrainMovementTest, TurnoutW1StraightLeadsIntoTheThroughTrack) {
    placeBr218("Einfahrt West", 1000);
    station_.receive(test::switchAccessory(W1, 1));
    ASSERT_TRUE(test::waitFor([&] { return station_.accessoryPosition(W1) == 1; }));
    station_.receive(test::speed(Br218, 1000));
    run(3s);
    EXPECT_EQ(contacts_.events, (std::vector<ContactEvent>{{1, true}, {7, false}}));
}

TEST_F(TrainMovementTest, SidingBehindW3EndsAtTheBufferStop) {
    placeBr218("Ausfahrt Ost", 1000);
    station_.receive(test::switchAccessory(W3, Round));
    ASSERT_TRUE(test::waitFor([&] { return station_.accessoryPosition(W3) == Round; }));
    station_.receive(test::speed(Br218, 1000));
    run(10s);
    EXPECT_EQ(contacts_.events, (std::vector<ContactEvent>{{9, true}, {8, false}}));
    EXPECT_EQ(movement_->position(Br218)->section, section("Abstellgleis"));
    EXPECT_EQ(movement_->position(Br218)->frontMm, 1000);
}

TEST_F(TrainMovementTest, TrackLoadGrowsWithRunningTrainsAndTheirSpeed) {
    placeBr218("Gleis 1", 1000);
    const int idle = movement_->trackLoad();
    EXPECT_GT(idle, 0);
    station_.receive(test::speed(Br218, 300));
    run(100ms);
    const int slow = movement_->trackLoad();
    station_.receive(test::speed(Br218, 1000));
    run(100ms);
    EXPECT_GT(slow, idle);
    EXPECT_GT(movement_->trackLoad(), slow);
}

TEST_F(TrainMovementTest, TimerMovesTrainsOnTheEventLoop) {
    TrainTrack track = TrainTrack::demo();
    track.placements = {{Br218, *track.find("Gleis 1"), 1000}};
    TrainMovement movement(station_, std::move(track), {.tick = 10ms});
    movement.start();
    station_.receive(test::speed(Br218, 1000));
    EXPECT_TRUE(test::waitFor([&] { return movement.position(Br218)->frontMm > 1100; }));
}

} // namespace
} // namespace stellwerk::sim
