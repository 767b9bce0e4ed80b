#pragma once

// Helpers shared by the transport tests: recognisable frames, waiting on the event loop, free ports and a
// recorder of what a transport delivered.

#include "can/FrameText.h"
#include "cs2/Header.h"
#include "transport/Transport.h"
#include "transport/TransportSettings.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTcpServer>
#include <QTest>
#include <chrono>
#include <cstdint>
#include <functional>
#include <gtest/gtest.h>
#include <initializer_list>
#include <ostream>
#include <vector>

namespace stellwerk::cs2 {
// Failed comparisons show frames as the protocol document writes them.
inline void PrintTo(const CanFrame& frame, std::ostream* out) {
    *out << formatDocument(frame);
}
} // namespace stellwerk::cs2

namespace stellwerk::transport::test {

using can::CanFrame;
using namespace std::chrono_literals;

// Long enough for a loaded two-core machine; waits end as soon as the condition holds.
inline constexpr int WaitMs = 3000;

inline bool waitFor(const std::function<bool()>& condition, int timeoutMs = WaitMs) {
    return QTest::qWaitFor(condition, timeoutMs);
}

inline CanFrame frame(std::uint32_t id, std::initializer_list<std::uint8_t> data) {
    CanFrame result;
    result.id = id;
    result.dlc = std::uint8_t(data.size());
    std::copy(data.begin(), data.end(), result.data.begin());
    return result;
}

// Frame number n of a sequence: a loco speed command whose payload carries n, so order can be checked.
inline CanFrame numbered(std::uint16_t n) {
    return frame(cs2::makeId(0, 0x04, false, 0x4711),
                 {0x00, 0x00, 0x40, 0x05, std::uint8_t(n >> 8), std::uint8_t(n)});
}

inline std::vector<CanFrame> numberedFrames(std::size_t count, std::uint16_t first = 0) {
    std::vector<CanFrame> frames;
    for (std::size_t i = 0; i < count; ++i)
        frames.push_back(numbered(std::uint16_t(first + i)));
    return frames;
}

// Retries quickly so that reconnection tests take milliseconds.
inline ReconnectTiming fastReconnect() {
    return {20ms, 80ms, 1000ms};
}

// A TCP port on 127.0.0.1 that nobody listens on right now.
inline std::uint16_t freeTcpPort() {
    QTcpServer probe;
    EXPECT_TRUE(probe.listen(QHostAddress::LocalHost, 0));
    return probe.serverPort();
}

// What a transport delivered: every batch as it came, when it came, and the problems it reported.
class Recorder {
public:
    explicit Recorder(Transport& transport) {
        clock_.start();
        QObject::connect(&transport, &Transport::framesReceived, &context_,
                         [this](const std::vector<CanFrame>& frames) {
                             batches.push_back(frames);
                             batchTimesNs.push_back(clock_.nsecsElapsed());
                         });
        QObject::connect(&transport, &Transport::problem, &context_,
                         [this](const QString& message) { problems.push_back(message); });
        QObject::connect(&transport, &Transport::stateChanged, &context_,
                         [this](Transport::State state) { states.push_back(state); });
    }

    std::vector<CanFrame> frames() const {
        std::vector<CanFrame> all;
        for (const auto& batch : batches)
            all.insert(all.end(), batch.begin(), batch.end());
        return all;
    }
    std::size_t frameCount() const { return frames().size(); }
    // Forgets the frames recorded so far.
    void clearFrames() {
        batches.clear();
        batchTimesNs.clear();
    }
    bool waitForFrames(std::size_t count, int timeoutMs = WaitMs) const {
        return waitFor([&] { return frameCount() >= count; }, timeoutMs);
    }

    std::vector<std::vector<CanFrame>> batches;
    std::vector<qint64> batchTimesNs;
    std::vector<QString> problems;
    std::vector<Transport::State> states;

private:
    QObject context_;
    QElapsedTimer clock_;
};

inline bool waitForState(const Transport& transport, Transport::State state, int timeoutMs = WaitMs) {
    return waitFor([&] { return transport.state() == state; }, timeoutMs);
}

} // namespace stellwerk::transport::test
