// The in-process pair: frames cross in batches, an end that goes away is waited for, pacing holds.

#include "transport/LoopbackTransport.h"

#include "TestSupport.h"

namespace stellwerk::transport::test {
namespace {

using State = Transport::State;

struct Pair {
    LoopbackTransport app{QStringLiteral("app")};
    LoopbackTransport station{QStringLiteral("station")};

    Pair() { LoopbackTransport::join(app, station); }
    void open() {
        app.open();
        station.open();
    }
};

TEST(LoopbackTransport, EndsAreConnectedOnceBothAreOpen) {
    Pair pair;
    pair.app.open();
    EXPECT_EQ(pair.app.state(), State::Connecting);
    pair.station.open();
    EXPECT_EQ(pair.app.state(), State::Connected);
    EXPECT_EQ(pair.station.state(), State::Connected);
    EXPECT_EQ(pair.app.description(), QStringLiteral("loopback://app"));
}

TEST(LoopbackTransport, FramesArriveOnTheOtherEndAsOneBatch) {
    Pair pair;
    pair.open();
    Recorder station(pair.station);
    for (const CanFrame& frame : numberedFrames(100))
        EXPECT_TRUE(pair.app.send(frame));
    EXPECT_TRUE(station.batches.empty()) << "delivery waits for the event loop";
    ASSERT_TRUE(station.waitForFrames(100));
    EXPECT_EQ(station.batches.size(), 1u);
    EXPECT_EQ(station.frames(), numberedFrames(100));
    EXPECT_EQ(pair.app.counters().framesOut, 100u);
    EXPECT_EQ(pair.station.counters().framesIn, 100u);
}

TEST(LoopbackTransport, FramesCrossBothWays) {
    Pair pair;
    pair.open();
    Recorder app(pair.app);
    Recorder station(pair.station);
    EXPECT_EQ(pair.app.sendBatch(numberedFrames(3)), 3u);
    EXPECT_EQ(pair.station.sendBatch(numberedFrames(2, 10)), 2u);
    ASSERT_TRUE(station.waitForFrames(3));
    ASSERT_TRUE(app.waitForFrames(2));
    EXPECT_EQ(station.frames(), numberedFrames(3));
    EXPECT_EQ(app.frames(), numberedFrames(2, 10));
}

TEST(LoopbackTransport, SendOnAClosedEndIsRefusedAndCounted) {
    Pair pair;
    EXPECT_FALSE(pair.app.send(numbered(1)));
    EXPECT_EQ(pair.app.sendBatch(numberedFrames(3)), 0u);
    EXPECT_EQ(pair.app.counters().dropped, 4u);
    EXPECT_EQ(pair.app.counters().framesOut, 0u);
}

// What is said while the peer is away is refused, never delivered when it returns (issue 11).
TEST(LoopbackTransport, FramesSentWhileThePeerIsAwayAreRefusedAndNeverArrive) {
    Pair pair;
    pair.open();
    Recorder app(pair.app);
    pair.station.close();
    EXPECT_EQ(pair.app.state(), State::Reconnecting);
    EXPECT_TRUE(pair.app.refusesFrames());
    EXPECT_EQ(pair.app.sendBatch(numberedFrames(5)), 0u);
    EXPECT_EQ(pair.app.queuedFrames(), 0u);
    EXPECT_EQ(pair.app.counters().dropped, 5u);
    Recorder station(pair.station);
    pair.station.open();
    EXPECT_EQ(pair.app.state(), State::Connected);
    EXPECT_TRUE(pair.app.send(numbered(7)));
    ASSERT_TRUE(station.waitForFrames(1));
    EXPECT_EQ(station.frames(), std::vector{numbered(7)});
    EXPECT_EQ(pair.app.counters().reconnects, 1u);
    EXPECT_EQ(app.states, (std::vector{State::Reconnecting, State::Connected}));
}

// Frames that still wait for the wire when the connection is lost are dropped with it.
TEST(LoopbackTransport, FramesWaitingForPacingAreDroppedWhenTheConnectionIsLost) {
    Pair pair;
    pair.app.setPacing(50ms);
    pair.open();
    Recorder station(pair.station);
    EXPECT_EQ(pair.app.sendBatch(numberedFrames(4)), 4u);
    EXPECT_EQ(pair.app.queuedFrames(), 3u);
    pair.station.close();
    EXPECT_EQ(pair.app.queuedFrames(), 0u);
    EXPECT_EQ(pair.app.counters().dropped, 3u);
    pair.station.open();
    QTest::qWait(200);
    EXPECT_TRUE(station.frames().empty()) << "the first frame went with the station's end";
}

// A ticket takes back what of a command still waits; other frames keep their place.
TEST(LoopbackTransport, WithdrawnFramesNeverReachTheWire) {
    Pair pair;
    pair.app.setPacing(20ms);
    pair.open();
    Recorder station(pair.station);
    EXPECT_TRUE(pair.app.send(numbered(0), 1));
    EXPECT_TRUE(pair.app.send(numbered(1), 2));
    EXPECT_TRUE(pair.app.send(numbered(2), 3));
    EXPECT_TRUE(pair.app.send(numbered(3), 2));
    EXPECT_EQ(pair.app.withdraw(2), 2u);
    EXPECT_EQ(pair.app.withdraw(0), 0u) << "ticket 0 marks frames nobody withdraws";
    ASSERT_TRUE(station.waitForFrames(2));
    QTest::qWait(60);
    EXPECT_EQ(station.frames(), (std::vector{numbered(0), numbered(2)}));
    EXPECT_EQ(pair.app.counters().dropped, 2u);
}

TEST(LoopbackTransport, QueueLimitRefusesAndCountsDropped) {
    Pair pair;
    pair.app.setQueueLimit(3);
    pair.app.open();
    EXPECT_EQ(pair.app.queueLimit(), 3u);
    EXPECT_TRUE(pair.app.send(numbered(0)));
    EXPECT_EQ(pair.app.sendBatch(numberedFrames(4, 1)), 2u);
    EXPECT_FALSE(pair.app.send(numbered(5)));
    EXPECT_EQ(pair.app.counters().dropped, 3u);
    Recorder station(pair.station);
    pair.station.open();
    ASSERT_TRUE(station.waitForFrames(3));
    EXPECT_EQ(station.frames(), numberedFrames(3));
}

TEST(LoopbackTransport, CloseDiscardsWaitingFramesAndSaysSo) {
    Pair pair;
    Recorder app(pair.app);
    pair.app.open();
    pair.app.sendBatch(numberedFrames(4));
    pair.app.close();
    EXPECT_EQ(pair.app.counters().dropped, 4u);
    ASSERT_EQ(app.problems.size(), 1u);
    EXPECT_TRUE(app.problems[0].contains(QStringLiteral("4 frame(s) not sent")))
        << app.problems[0].toStdString();
}

TEST(LoopbackTransport, DestroyedPeerLeavesTheOtherEndWaiting) {
    LoopbackTransport app(QStringLiteral("app"));
    {
        LoopbackTransport station(QStringLiteral("station"));
        LoopbackTransport::join(app, station);
        app.open();
        station.open();
    }
    EXPECT_EQ(app.state(), State::Reconnecting);
    EXPECT_FALSE(app.send(numbered(1)));
    EXPECT_EQ(app.queuedFrames(), 0u);
}

// Paced frames cross one by one: each arrives in its own batch, the whole run takes at least the gaps.
TEST(LoopbackTransport, PacingSpacesFramesAndKeepsTheirOrder) {
    constexpr auto gap = 10ms;
    constexpr std::size_t count = 8;
    Pair pair;
    pair.app.setPacing(gap);
    EXPECT_EQ(pair.app.pacing(), gap);
    pair.open();
    Recorder station(pair.station);
    EXPECT_EQ(pair.app.sendBatch(numberedFrames(count)), count);
    ASSERT_TRUE(station.waitForFrames(count));
    EXPECT_EQ(station.frames(), numberedFrames(count));
    EXPECT_EQ(station.batches.size(), count);
    const qint64 span = station.batchTimesNs.back() - station.batchTimesNs.front();
    EXPECT_GE(span, std::chrono::nanoseconds(gap).count() * qint64(count - 1) * 8 / 10);
}

// What the app wrote, as the wire took it: one report per block, none for frames still waiting.
TEST(LoopbackTransport, FramesSentReportsEachBlockTheWireTook) {
    Pair pair;
    std::vector<std::vector<CanFrame>> sent;
    QObject::connect(&pair.app, &Transport::framesSent,
                     [&sent](const std::vector<CanFrame>& frames) { sent.push_back(frames); });
    pair.app.open();
    EXPECT_EQ(pair.app.sendBatch(numberedFrames(3)), 3u); // waits for the peer
    EXPECT_TRUE(sent.empty());
    pair.station.open();
    ASSERT_EQ(sent.size(), 1u);
    EXPECT_EQ(sent[0], numberedFrames(3));
    EXPECT_EQ(pair.app.sendBatch(numberedFrames(4, 3)), 4u);
    ASSERT_EQ(sent.size(), 2u);
    EXPECT_EQ(sent[1], numberedFrames(4, 3));
}

TEST(LoopbackTransport, FramesSentFollowsPacingOneFrameAtATime) {
    constexpr std::size_t count = 5;
    Pair pair;
    pair.app.setPacing(5ms);
    pair.open();
    std::vector<std::vector<CanFrame>> sent;
    QObject::connect(&pair.app, &Transport::framesSent,
                     [&sent](const std::vector<CanFrame>& frames) { sent.push_back(frames); });
    EXPECT_EQ(pair.app.sendBatch(numberedFrames(count)), count);
    EXPECT_LT(sent.size(), count) << "paced frames wait for their gap";
    ASSERT_TRUE(waitFor([&] { return sent.size() == count; }));
    std::vector<CanFrame> all;
    for (const auto& block : sent) {
        EXPECT_EQ(block.size(), 1u);
        all.insert(all.end(), block.begin(), block.end());
    }
    EXPECT_EQ(all, numberedFrames(count));
    EXPECT_EQ(pair.app.counters().framesOut, count);
}

TEST(LoopbackTransport, RefusedFramesAreNotReportedAsSent) {
    Pair pair;
    int reports = 0;
    QObject::connect(&pair.app, &Transport::framesSent,
                     [&reports](const std::vector<CanFrame>&) { ++reports; });
    EXPECT_FALSE(pair.app.send(numbered(1))); // closed
    pair.app.open();
    pair.app.setQueueLimit(2);
    EXPECT_EQ(pair.app.sendBatch(numberedFrames(3)), 2u); // no peer yet: two wait, one is refused
    pair.app.close();
    EXPECT_EQ(reports, 0);
}

} // namespace
} // namespace stellwerk::transport::test
