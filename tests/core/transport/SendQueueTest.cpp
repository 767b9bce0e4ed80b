// The send queue: frames wait while the wire is away, a full queue refuses, pacing spaces frames out.

#include "transport/SendQueue.h"

#include "TestSupport.h"

namespace stellwerk::transport::test {
namespace {

// A wire that records every write: the frames and when they were written.
struct Wire {
    QObject owner;
    std::vector<std::vector<CanFrame>> writes;
    std::vector<qint64> writeTimesNs;
    QElapsedTimer clock;
    SendQueue queue{&owner, [this](std::span<const CanFrame> frames) {
                        writes.emplace_back(frames.begin(), frames.end());
                        writeTimesNs.push_back(clock.nsecsElapsed());
                    }};

    Wire() { clock.start(); }
    std::vector<CanFrame> written() const {
        std::vector<CanFrame> all;
        for (const auto& write : writes)
            all.insert(all.end(), write.begin(), write.end());
        return all;
    }
};

TEST(SendQueue, WritableWireGetsFramesAtOnceAsOneBlock) {
    Wire wire;
    wire.queue.setWritable(true);
    const auto frames = numberedFrames(5);
    EXPECT_EQ(wire.queue.push(frames), 5u);
    ASSERT_EQ(wire.writes.size(), 1u);
    EXPECT_EQ(wire.writes[0], frames);
    EXPECT_EQ(wire.queue.size(), 0u);
}

TEST(SendQueue, FramesWaitForTheWireAndThenGoOutInOrderAsOneBlock) {
    Wire wire;
    EXPECT_EQ(wire.queue.push(numberedFrames(3)), 3u);
    EXPECT_EQ(wire.queue.push(numberedFrames(2, 3)), 2u);
    EXPECT_TRUE(wire.writes.empty());
    EXPECT_EQ(wire.queue.size(), 5u);
    wire.queue.setWritable(true);
    ASSERT_EQ(wire.writes.size(), 1u);
    EXPECT_EQ(wire.writes[0], numberedFrames(5));
}

TEST(SendQueue, FullQueueRefusesTheRest) {
    Wire wire;
    wire.queue.setLimit(4);
    EXPECT_EQ(wire.queue.push(numberedFrames(3)), 3u);
    EXPECT_EQ(wire.queue.push(numberedFrames(3, 3)), 1u);
    EXPECT_EQ(wire.queue.push(numberedFrames(1, 6)), 0u);
    wire.queue.setWritable(true);
    EXPECT_EQ(wire.written(), numberedFrames(4));
}

TEST(SendQueue, DiscardForgetsWaitingFrames) {
    Wire wire;
    wire.queue.push(numberedFrames(3));
    EXPECT_EQ(wire.queue.discard(), 3u);
    wire.queue.setWritable(true);
    EXPECT_TRUE(wire.writes.empty());
}

TEST(SendQueue, PacingKeepsTheGapAndTheOrder) {
    constexpr auto gap = 10ms;
    Wire wire;
    wire.queue.setPacing(gap);
    wire.queue.setWritable(true);
    EXPECT_EQ(wire.queue.push(numberedFrames(8)), 8u);
    EXPECT_EQ(wire.writes.size(), 1u) << "the first frame goes at once";
    ASSERT_TRUE(waitFor([&] { return wire.writes.size() == 8; }));
    EXPECT_EQ(wire.written(), numberedFrames(8));
    for (std::size_t i = 1; i < wire.writeTimesNs.size(); ++i) {
        EXPECT_EQ(wire.writes[i].size(), 1u);
        EXPECT_GE(wire.writeTimesNs[i] - wire.writeTimesNs[i - 1],
                  std::chrono::nanoseconds(gap).count() * 8 / 10)
            << "between frames " << i - 1 << " and " << i;
    }
}

TEST(SendQueue, PacedFramesWaitForTheWireToo) {
    constexpr auto gap = 5ms;
    Wire wire;
    wire.queue.setPacing(gap);
    wire.queue.push(numberedFrames(4));
    EXPECT_TRUE(wire.writes.empty());
    wire.queue.setWritable(true);
    ASSERT_TRUE(waitFor([&] { return wire.writes.size() == 4; }));
    EXPECT_EQ(wire.written(), numberedFrames(4));
}

TEST(SendQueue, PacingLimitsWaitingFramesToo) {
    Wire wire;
    wire.queue.setPacing(50ms);
    wire.queue.setLimit(2);
    wire.queue.setWritable(true);
    EXPECT_EQ(wire.queue.push(numberedFrames(5)), 3u) << "one written at once, two waiting";
}

TEST(SendQueue, WireThatGoesAwayStopsPacedFrames) {
    Wire wire;
    wire.queue.setPacing(5ms);
    wire.queue.setWritable(true);
    wire.queue.push(numberedFrames(3));
    wire.queue.setWritable(false);
    QTest::qWait(30);
    EXPECT_EQ(wire.writes.size(), 1u);
    EXPECT_EQ(wire.queue.size(), 2u);
}

} // namespace
} // namespace stellwerk::transport::test
