// Document 1.2.3/1.2.5: a command counts as carried out only when its acknowledgement arrives: the same
// command with the response bit and the same payload, from any sender.

#include "ScriptedStation.h"
#include "station/AckKey.h"

namespace stellwerk::station::test {
namespace {

using Status = CommandResult::Status;

cs2::Message speed(std::uint32_t loco, std::uint16_t value) {
    return {0, false, 0, cs2::LocoSpeed{cs2::LocId(loco), value}};
}

struct Outcome {
    std::optional<CommandResult> result;
    CommandCallback callback() {
        return [this](const CommandResult& r) { result = r; };
    }
    bool arrived() const { return result.has_value(); }
};

TEST(CommandTracker, LocoSpeedIsAcknowledgedByItsEchoWithTheResponseBit) {
    Bench bench;
    Outcome outcome;
    EXPECT_NE(bench.session.request(speed(0x4006, 500), outcome.callback()), 0u);
    EXPECT_EQ(bench.session.tracker().pendingCount(), 1u);
    ASSERT_TRUE(waitFor([&] { return outcome.arrived(); }));
    EXPECT_EQ(outcome.result->status, Status::Acknowledged);
    EXPECT_EQ(outcome.result->attempts, 1);
    ASSERT_TRUE(outcome.result->answer);
    EXPECT_TRUE(outcome.result->answer->response);
    EXPECT_EQ(std::get<cs2::LocoSpeed>(outcome.result->answer->body).speed, 500);
    EXPECT_EQ(bench.session.tracker().pendingCount(), 0u);
}

TEST(CommandTracker, AnAnswerForAnotherLocIdDoesNotCompleteOurs) {
    Bench bench;
    bench.station.script = [](const CanFrame& f) {
        // Another loco's acknowledgement, carrying our hash: matching by hash alone would accept it.
        return std::vector<CanFrame>{frame(0x04, true, cs2::hash(f), {0, 0, 0x40, 0x07, 0x01, 0xF4})};
    };
    Outcome outcome;
    bench.session.request(speed(0x4006, 500), outcome.callback(), CommandPolicy{60ms, 0});
    ASSERT_TRUE(waitFor([&] { return outcome.arrived(); }));
    EXPECT_EQ(outcome.result->status, Status::TimedOut);
}

TEST(CommandTracker, TheSameLocoWithAnotherFunctionDoesNotCompleteOurs) {
    const auto ours = ackKeyOf({0, false, 0, cs2::LocoFunction{cs2::LocId(0x4006), 3, 1, std::nullopt}});
    const auto other = ackKeyOf({0, true, 0, cs2::LocoFunction{cs2::LocId(0x4006), 4, 1, std::nullopt}});
    const auto same = ackKeyOf({0, true, 0x1234, cs2::LocoFunction{cs2::LocId(0x4006), 3, 1, std::nullopt}});
    ASSERT_TRUE(ours && other && same);
    EXPECT_NE(*ours, *other);
    EXPECT_EQ(*ours, *same);
}

TEST(CommandTracker, MissingAcknowledgementIsSentAgainAndTheSecondTrySucceeds) {
    Bench bench;
    bench.station.dropFirst = 1;
    Outcome outcome;
    bench.session.request(speed(0x4006, 250), outcome.callback(), CommandPolicy{100ms, 2});
    ASSERT_TRUE(waitFor([&] { return outcome.arrived(); }));
    EXPECT_EQ(outcome.result->status, Status::Acknowledged);
    EXPECT_GE(outcome.result->attempts, 2);
    EXPECT_GE(bench.station.count(cs2::Command::LocoSpeed), 2u);
    EXPECT_GE(bench.session.tracker().retriesSent(), 1u);
}

TEST(CommandTracker, NoAcknowledgementFailsAfterTheRetries) {
    Bench bench;
    bench.station.silent = true;
    Outcome outcome;
    bench.session.request(speed(0x4006, 250), outcome.callback(), CommandPolicy{30ms, 2});
    ASSERT_TRUE(waitFor([&] { return outcome.arrived(); }));
    EXPECT_EQ(outcome.result->status, Status::TimedOut);
    EXPECT_EQ(outcome.result->attempts, 3);
    EXPECT_EQ(bench.station.count(cs2::Command::LocoSpeed), 3u) << "first send + 2 retries, then no more";
    QTest::qWait(100);
    EXPECT_EQ(bench.station.count(cs2::Command::LocoSpeed), 3u);
}

TEST(CommandTracker, RefusedConfigurationValueIsRejected) {
    // 2.12: setting a configuration value (DLC 8) is answered with DLC 7 and FALSE when invalid.
    Bench bench;
    bench.station.script = [](const CanFrame& f) {
        return std::vector<CanFrame>{
            frame(0x00, true, ScriptedStation::Hash,
                  {f.data[0], f.data[1], f.data[2], f.data[3], 0x0B, f.data[5], 0x00})};
    };
    cs2::SystemStatus set;
    set.device = ScriptedStation::Uid;
    set.channel = 5;
    set.value = 700;
    Outcome outcome;
    bench.session.request({0, false, 0, set}, outcome.callback());
    ASSERT_TRUE(waitFor([&] { return outcome.arrived(); }));
    EXPECT_EQ(outcome.result->status, Status::Rejected);
}

TEST(CommandTracker, TwoCommandsForTheSameLocoAreAnsweredInOrder) {
    Bench bench;
    Outcome first;
    Outcome second;
    bench.session.request(speed(0x4006, 100), first.callback());
    bench.session.request(speed(0x4006, 200), second.callback());
    ASSERT_TRUE(waitFor([&] { return first.arrived() && second.arrived(); }));
    EXPECT_EQ(std::get<cs2::LocoSpeed>(first.result->answer->body).speed, 100);
    EXPECT_EQ(std::get<cs2::LocoSpeed>(second.result->answer->body).speed, 200);
}

TEST(CommandTracker, PingHasNoSingleAnswerAndIsNotTracked) {
    Bench bench;
    Outcome outcome;
    EXPECT_EQ(bench.session.request({0, false, 0, cs2::Ping{}}, outcome.callback()), 0u);
    ASSERT_TRUE(outcome.arrived());
    EXPECT_EQ(outcome.result->status, Status::NotSent);
}

} // namespace
} // namespace stellwerk::station::test
