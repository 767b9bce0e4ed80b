// Issue 32: a command the station did not confirm may still be carried out (a stalled station reads its
// copies when it wakes). The book says what to bring back, when, and what it must never do: make a train
// faster, start one, or switch the track power on.

#include "model/UnconfirmedCommands.h"

#include <gtest/gtest.h>

namespace stellwerk::model {
namespace {

using namespace std::chrono_literals;
using Clock = UnconfirmedCommands::Clock;

constexpr std::uint32_t Loco = 0x4006;
const Clock::time_point T0 = Clock::time_point{} + 1000s;

TEST(UnconfirmedCommands, AFailedSpeedIsAskedForWhenTheStationIsHeardAgainAndUndoneWhenItRuns) {
    UnconfirmedCommands book;
    const auto speed = CommandTarget::speed(Loco);
    book.failed(speed, 200, 40);
    const Recovery recovery = book.heardAgain(T0);
    EXPECT_TRUE(recovery.corrections.empty()) << "a locomotive's state can be asked for first";
    ASSERT_EQ(recovery.queries, std::vector{speed});
    EXPECT_TRUE(book.heardAgain(T0 + 1ms).queries.empty()) << "asked once, not at every answer";
    const auto correction = book.reported(speed, 200, T0 + 10ms);
    ASSERT_TRUE(correction.has_value());
    EXPECT_EQ(correction->target, speed);
    EXPECT_EQ(correction->failedValue, 200);
    EXPECT_EQ(correction->sentValue, 40);
    EXPECT_TRUE(correction->carriedOutLate);
    EXPECT_FALSE(book.reported(speed, 200, T0 + 11ms).has_value()) << "being brought back already";
}

TEST(UnconfirmedCommands, AFailedSpeedTheStationDidNotCarryOutNeedsNothing) {
    UnconfirmedCommands book;
    const auto speed = CommandTarget::speed(Loco);
    book.failed(speed, 200, 40);
    book.heardAgain(T0);
    EXPECT_FALSE(book.reported(speed, 40, T0 + 10ms).has_value());
    book.settle(T0 + 10ms + UnconfirmedCommands::WatchTime);
    EXPECT_TRUE(book.empty());
}

TEST(UnconfirmedCommands, AnUnansweredQuestionIsAskedAgainWhenTheStationIsNextHeard) {
    UnconfirmedCommands book;
    const auto direction = CommandTarget::direction(Loco);
    book.failed(direction, 1, 0);
    ASSERT_EQ(book.heardAgain(T0).queries.size(), 1U);
    book.queryUnanswered(direction);
    EXPECT_EQ(book.heardAgain(T0 + 1s).queries, std::vector{direction});
}

TEST(UnconfirmedCommands, ALocomotiveWithoutAConfirmedSpeedIsBroughtBackToZero) {
    UnconfirmedCommands book;
    const auto speed = CommandTarget::speed(Loco);
    book.failed(speed, 150, std::nullopt);
    book.failed(speed, 300, std::nullopt);
    const auto correction = book.reported(speed, 300, T0);
    ASSERT_TRUE(correction.has_value());
    EXPECT_EQ(correction->sentValue, 0);
}

TEST(UnconfirmedCommands, AFailedSlowerSpeedIsNotUndoneByMakingTheTrainFaster) {
    UnconfirmedCommands book;
    book.failed(CommandTarget::speed(Loco), 100, 500);
    const auto late = book.reported(CommandTarget::speed(Loco), 100, T0 + 10ms);
    ASSERT_TRUE(late.has_value()) << "the person is told that it was carried out late";
    EXPECT_TRUE(late->carriedOutLate);
    EXPECT_FALSE(late->sentValue.has_value()) << "left as the station has it";
    EXPECT_EQ(book.restoreValue(CommandTarget::speed(Loco)), 100);
}

TEST(UnconfirmedCommands, ALateCopyWhileWatchedIsCorrectedAgainAndForgottenAfterTheWatch) {
    UnconfirmedCommands book;
    const auto speed = CommandTarget::speed(Loco);
    book.failed(speed, 200, 0);
    ASSERT_TRUE(book.reported(speed, 200, T0).has_value());
    book.acknowledged(speed, 0, T0 + 50ms); // the correction's answer
    const auto again = book.reported(speed, 200, T0 + 1s);
    ASSERT_TRUE(again.has_value());
    EXPECT_TRUE(again->carriedOutLate);
    EXPECT_EQ(again->sentValue, 0);
    book.acknowledged(speed, 0, T0 + 1050ms);
    book.settle(T0 + 1050ms + UnconfirmedCommands::WatchTime);
    EXPECT_FALSE(book.watches(speed));
    EXPECT_FALSE(book.reported(speed, 200, T0 + 10s).has_value()) << "later, 200 is someone's wish";
}

TEST(UnconfirmedCommands, AnotherControllersChangeIsLeftAndBecomesTheValueToBringBack) {
    UnconfirmedCommands book;
    const auto speed = CommandTarget::speed(Loco);
    book.failed(speed, 700, 100);
    book.heardAgain(T0);
    EXPECT_FALSE(book.reported(speed, 250, T0 + 1ms).has_value()) << "not undone";
    EXPECT_EQ(book.restoreValue(speed), 250);
    const auto late = book.reported(speed, 700, T0 + 2ms);
    ASSERT_TRUE(late.has_value());
    EXPECT_EQ(late->sentValue, 250);
}

TEST(UnconfirmedCommands, AnAcknowledgedCommandIsTheNewConfirmedValue) {
    UnconfirmedCommands book;
    const auto speed = CommandTarget::speed(Loco);
    book.failed(speed, 600, 0);
    book.acknowledged(speed, 300, T0);
    EXPECT_EQ(book.restoreValue(speed), 300);
    const auto late = book.reported(speed, 600, T0 + 100ms);
    ASSERT_TRUE(late.has_value());
    EXPECT_EQ(late->sentValue, 300);
}

TEST(UnconfirmedCommands, AFailedGoIsUndoneButAFailedStopIsNeverUndoneByGo) {
    UnconfirmedCommands go;
    go.failed(CommandTarget::power(), 1, 0);
    const auto off = go.heardAgain(T0).corrections;
    ASSERT_EQ(off.size(), 1U) << "the station cannot report its power: sent back at once";
    EXPECT_EQ(off[0].sentValue, 0);

    UnconfirmedCommands unknownPower;
    unknownPower.failed(CommandTarget::power(), 1, std::nullopt);
    ASSERT_EQ(unknownPower.heardAgain(T0).corrections.size(), 1U) << "power not reported counts as off";

    UnconfirmedCommands stop;
    stop.failed(CommandTarget::power(), 0, 1);
    EXPECT_TRUE(stop.heardAgain(T0).corrections.empty());
    const auto late = stop.reported(CommandTarget::power(), 0, T0 + 1ms);
    ASSERT_TRUE(late.has_value());
    EXPECT_FALSE(late->sentValue.has_value());
}

TEST(UnconfirmedCommands, AccessoriesGoBackAtOnceToTheirConfirmedPositionOrStayWhenNoneIsKnown) {
    UnconfirmedCommands book;
    book.failed(CommandTarget::accessory(3), 1, 0);
    book.failed(CommandTarget::accessory(4), 1, std::nullopt);
    book.failed(CommandTarget::function(Loco, 2), 1, 0);
    const Recovery recovery = book.heardAgain(T0);
    ASSERT_EQ(recovery.corrections.size(), 1U);
    EXPECT_EQ(recovery.corrections[0].target, CommandTarget::accessory(3));
    EXPECT_EQ(recovery.corrections[0].sentValue, 0);
    EXPECT_EQ(recovery.queries, std::vector{CommandTarget::function(Loco, 2)});
    const auto function = book.reported(CommandTarget::function(Loco, 2), 1, T0 + 1ms);
    ASSERT_TRUE(function.has_value());
    EXPECT_EQ(function->sentValue, 0);
    const auto unknown = book.reported(CommandTarget::accessory(4), 1, T0 + 1ms);
    ASSERT_TRUE(unknown.has_value()) << "told, though there is nothing to bring back";
    EXPECT_FALSE(unknown->sentValue.has_value());
}

TEST(UnconfirmedCommands, TheStopAftermathStopsEachLocomotiveOnceWhateverItsFailedCommands) {
    UnconfirmedCommands book;
    book.setAftermath(Aftermath::StopLocomotives);
    book.failed(CommandTarget::function(Loco, 1), 1, 0);
    book.failed(CommandTarget::direction(Loco), 1, 0);
    book.failed(CommandTarget::speed(Loco), 50, 400);
    book.failed(CommandTarget::accessory(7), 1, 0);
    const Recovery recovery = book.heardAgain(T0);
    EXPECT_TRUE(recovery.queries.empty()) << "stopping needs no question";
    const auto& corrections = recovery.corrections;
    ASSERT_EQ(corrections.size(), 2U);
    EXPECT_EQ(corrections[0].target, CommandTarget::speed(Loco));
    EXPECT_EQ(corrections[0].sentValue, 0);
    EXPECT_EQ(corrections[1].target, CommandTarget::accessory(7));
    book.acknowledged(CommandTarget::speed(Loco), 0, T0 + 10ms);
    const auto lateDirection = book.reported(CommandTarget::direction(Loco), 1, T0 + 20ms);
    ASSERT_TRUE(lateDirection.has_value());
    EXPECT_EQ(lateDirection->target, CommandTarget::speed(Loco)) << "a late copy stops it again";
    EXPECT_EQ(lateDirection->sentValue, 0);
    book.acknowledged(CommandTarget::speed(Loco), 0, T0 + 30ms);
    book.settle(T0 + 30ms + UnconfirmedCommands::WatchTime);
    EXPECT_EQ(book.size(), 1U) << "only the accessory still waits for its answer";
}

TEST(UnconfirmedCommands, ACorrectionThatFailsIsTriedAgainWhenTheStationIsNextHeard) {
    UnconfirmedCommands book;
    const auto power = CommandTarget::power();
    book.failed(power, 1, 0);
    ASSERT_EQ(book.heardAgain(T0).corrections.size(), 1U);
    book.failed(power, 0, std::nullopt); // the correction itself got no answer
    const auto again = book.heardAgain(T0 + 2s).corrections;
    ASSERT_EQ(again.size(), 1U);
    EXPECT_EQ(again[0].failedValue, 1);
    EXPECT_EQ(again[0].sentValue, 0);
}

} // namespace
} // namespace stellwerk::model
