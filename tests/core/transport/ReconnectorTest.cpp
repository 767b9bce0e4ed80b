// Reconnection timing: doubling back-off up to a maximum, reset by a success, hanging attempts given up.

#include "transport/Reconnector.h"

#include "TestSupport.h"

namespace stellwerk::transport::test {
namespace {

struct Attempts {
    QObject owner;
    int made = 0;
    int timedOut = 0;
    Reconnector reconnector{&owner, [this] { ++made; }, [this] { ++timedOut; }};

    explicit Attempts(ReconnectTiming timing) { reconnector.setTiming(timing); }
};

TEST(Reconnector, FirstAttemptIsMadeAtOnce) {
    Attempts attempts({20ms, 80ms, 1000ms});
    attempts.reconnector.start();
    EXPECT_EQ(attempts.made, 1);
    EXPECT_FALSE(attempts.reconnector.isWaiting());
}

TEST(Reconnector, DelaysDoubleUpToTheMaximum) {
    Attempts attempts({250ms, 5000ms, 0ms});
    attempts.reconnector.start();
    std::vector<std::chrono::milliseconds> delays;
    for (int i = 0; i < 7; ++i) {
        delays.push_back(attempts.reconnector.lost());
        attempts.reconnector.stop();
    }
    const std::vector<std::chrono::milliseconds> expected{250ms,  500ms,  1000ms, 2000ms,
                                                          4000ms, 5000ms, 5000ms};
    EXPECT_EQ(delays, expected);
}

TEST(Reconnector, RetryMakesTheNextAttemptAfterTheDelay) {
    Attempts attempts({20ms, 80ms, 1000ms});
    attempts.reconnector.start();
    attempts.reconnector.lost();
    EXPECT_TRUE(attempts.reconnector.isWaiting());
    EXPECT_EQ(attempts.made, 1);
    ASSERT_TRUE(waitFor([&] { return attempts.made == 2; }));
    EXPECT_FALSE(attempts.reconnector.isWaiting());
}

TEST(Reconnector, SuccessResetsTheDelayAndTellsAReconnection) {
    Attempts attempts({20ms, 80ms, 1000ms});
    attempts.reconnector.start();
    EXPECT_FALSE(attempts.reconnector.connected()) << "the first connection";
    EXPECT_EQ(attempts.reconnector.lost(), 20ms);
    EXPECT_EQ(attempts.reconnector.lost(), 20ms) << "already waiting: the delay does not grow";
    attempts.reconnector.stop();
    attempts.reconnector.start();
    EXPECT_FALSE(attempts.reconnector.connected()) << "start() begins a new session";
    attempts.reconnector.lost();
    ASSERT_TRUE(waitFor([&] { return attempts.made == 3; }));
    EXPECT_TRUE(attempts.reconnector.connected());
    EXPECT_EQ(attempts.reconnector.lost(), 20ms);
}

TEST(Reconnector, HangingAttemptIsGivenUp) {
    Attempts attempts({20ms, 80ms, 30ms});
    attempts.reconnector.start();
    ASSERT_TRUE(waitFor([&] { return attempts.timedOut == 1; }));
}

TEST(Reconnector, SuccessfulAttemptIsNotGivenUp) {
    Attempts attempts({20ms, 80ms, 20ms});
    attempts.reconnector.start();
    attempts.reconnector.connected();
    QTest::qWait(60);
    EXPECT_EQ(attempts.timedOut, 0);
}

TEST(Reconnector, StopCancelsTheRetry) {
    Attempts attempts({10ms, 80ms, 1000ms});
    attempts.reconnector.start();
    attempts.reconnector.lost();
    attempts.reconnector.stop();
    QTest::qWait(40);
    EXPECT_EQ(attempts.made, 1);
}

} // namespace
} // namespace stellwerk::transport::test
