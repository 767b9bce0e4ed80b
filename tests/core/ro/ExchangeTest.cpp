// The stop-and-wait rules of one request (notes B3.3; the document gives no timeouts, no retry rule and
// no job id in 0xFE): a timeout resends with the same job id, 0xFD tells a lost answer from a module that
// remembers the id, 0xFE ends the request, stale answers are waited past.
#include "ro/Exchange.h"

#include <gtest/gtest.h>

namespace stellwerk::ro {
namespace {

struct Fixture {
    std::uint8_t nextJob = 0x36;
    Exchange exchange;

    explicit Fixture(Request request)
        : exchange(
              request, [this] { return nextJob++; }, Exchange::Limits{2, 2}) {
        exchange.sent();
    }
};

const Request RelayWrite{Request::Kind::Write, Width::Word, 0x0000, 0x35, 0x2000}; // 004 §3.4
const Request InputRead{Request::Kind::Read, Width::Word, 0x0020, 0x35};

TEST(RoExchange, OkWithTheJobIdEndsTheRequest) {
    Fixture f(InputRead);
    const Step step = f.exchange.answered(OkAnswer{Width::Word, 0x35, 0x0102});
    ASSERT_EQ(step.kind, Step::Kind::Finish);
    EXPECT_EQ(step.outcome->kind, Outcome::Kind::Done);
    EXPECT_EQ(step.outcome->value, 0x0102u);
}

TEST(RoExchange, StaleAnswersAreWaitedPast) {
    Fixture f(RelayWrite);
    EXPECT_EQ(f.exchange.answered(OkAnswer{Width::None, 0x34}).kind, Step::Kind::Wait);
    EXPECT_EQ(f.exchange.answered(DuplicateJobAnswer{0x33}).kind, Step::Kind::Wait);
    EXPECT_EQ(f.exchange.answered(OkAnswer{Width::None, 0x35}).kind, Step::Kind::Finish);
}

TEST(RoExchange, TimeoutResendsTheSameJobIdTwiceThenGivesUp) {
    Fixture f(RelayWrite);
    for (int retry = 0; retry < 2; ++retry) {
        EXPECT_EQ(f.exchange.timedOut().kind, Step::Kind::Send);
        EXPECT_EQ(f.exchange.request().job, 0x35) << "same job id, so that 0xFD can tell a lost answer";
        f.exchange.sent();
    }
    const Step step = f.exchange.timedOut();
    ASSERT_EQ(step.kind, Step::Kind::Finish);
    EXPECT_EQ(step.outcome->kind, Outcome::Kind::NoAnswer);
    EXPECT_FALSE(step.outcome->succeeded());
}

TEST(RoExchange, DuplicateOnARetransmittedWriteConfirmsIt) {
    Fixture f(RelayWrite);
    f.exchange.timedOut(); // the answer was lost
    f.exchange.sent();
    const Step step = f.exchange.answered(DuplicateJobAnswer{0x35});
    ASSERT_EQ(step.kind, Step::Kind::Finish);
    EXPECT_EQ(step.outcome->kind, Outcome::Kind::ConfirmedByDuplicate);
    EXPECT_TRUE(step.outcome->succeeded());
}

TEST(RoExchange, DuplicateOnARetransmittedReadTakesItsDataOrReadsAgain) {
    Fixture withData(InputRead);
    withData.exchange.timedOut();
    withData.exchange.sent();
    Step step = withData.exchange.answered(DuplicateJobAnswer{0x35, 2, 0x0102}); // notes R10
    ASSERT_EQ(step.kind, Step::Kind::Finish);
    EXPECT_EQ(step.outcome->value, 0x0102u);

    Fixture without(InputRead);
    without.exchange.timedOut();
    without.exchange.sent();
    step = without.exchange.answered(DuplicateJobAnswer{0x35});
    ASSERT_EQ(step.kind, Step::Kind::Send);
    EXPECT_EQ(without.exchange.request().job, 0x36) << "a fresh job id, or the module answers 0xFD again";
    without.exchange.sent();
    step = without.exchange.answered(OkAnswer{Width::Word, 0x36, 7});
    ASSERT_EQ(step.kind, Step::Kind::Finish);
    EXPECT_EQ(step.outcome->value, 7u);
    EXPECT_TRUE(step.outcome->reissued) << "read-to-clear flags of the lost answer are reported lost";
}

TEST(RoExchange, DuplicateOnAFirstTransmissionTakesAFreshJobIdTwiceAtMost) {
    Fixture f(RelayWrite);
    for (std::uint8_t resync = 0; resync < 2; ++resync) {
        const std::uint8_t job = f.exchange.request().job;
        ASSERT_EQ(f.exchange.answered(DuplicateJobAnswer{job}).kind, Step::Kind::Send);
        EXPECT_EQ(f.exchange.request().job, 0x36 + resync);
        f.exchange.sent();
    }
    const Step step = f.exchange.answered(DuplicateJobAnswer{f.exchange.request().job});
    ASSERT_EQ(step.kind, Step::Kind::Finish);
    EXPECT_EQ(step.outcome->kind, Outcome::Kind::JobIdsExhausted);
}

TEST(RoExchange, InvalidCommandEndsTheRequestWithoutJobId) {
    Fixture f(RelayWrite);
    const Step step = f.exchange.answered(InvalidCommandAnswer{});
    ASSERT_EQ(step.kind, Step::Kind::Finish);
    EXPECT_EQ(step.outcome->kind, Outcome::Kind::InvalidCommand);
    EXPECT_EQ(step.outcome->text(), "invalid command (0xFE)");
}

} // namespace
} // namespace stellwerk::ro
