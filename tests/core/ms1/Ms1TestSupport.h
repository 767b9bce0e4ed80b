#pragma once

// Helpers of the MS1 tests: frames printed as the documents print them, frames written the same way,
// what a peer emitted, and waiting on the event loop.

#include "EventLoopWait.h"
#include "can/FrameText.h"
#include "mcan/Codec.h"
#include "sim/SimulatedMs1.h"

#include <QObject>
#include <QTest>
#include <QTimer>
#include <algorithm>
#include <functional>
#include <gtest/gtest.h>
#include <ostream>
#include <string_view>
#include <vector>

namespace stellwerk::can {
// Failed comparisons show frames as the protocol document writes them.
inline void PrintTo(const CanFrame& frame, std::ostream* out) {
    *out << formatDocument(frame);
}
} // namespace stellwerk::can

namespace stellwerk::sim::test {

using can::CanFrame;

// Long enough for a loaded two-core machine; waits end as soon as the condition holds.
inline constexpr int WaitMs = 5000;

// Runs the event loop until the condition holds, each event as it comes: a conversation on the simulated
// bus takes one turn of the loop per exchange (support::runEventsUntil).
inline bool waitFor(const std::function<bool()>& condition, int timeoutMs = WaitMs) {
    return support::runEventsUntil(condition, timeoutMs);
}

// "1C00007E 0" or "180009AB 4 80 02 00 00": identifier, DLC, data, as the notes print them.
inline CanFrame frame(std::string_view documentLine) {
    auto parsed = can::parseFrame(documentLine);
    EXPECT_TRUE(parsed.hasValue()) << documentLine;
    return parsed ? parsed->frame : CanFrame{};
}

inline std::vector<CanFrame> frames(std::initializer_list<std::string_view> lines) {
    std::vector<CanFrame> result;
    for (const std::string_view line : lines)
        result.push_back(frame(line));
    return result;
}

// Everything a peer emitted, in order.
class Emitted {
public:
    template <typename Peer>
    explicit Emitted(Peer& peer) {
        QObject::connect(&peer, &Peer::framesEmitted, &context_, [this](const std::vector<CanFrame>& batch) {
            all.insert(all.end(), batch.begin(), batch.end());
        });
    }

    std::size_t count(const CanFrame& wanted) const { return std::size_t(std::ranges::count(all, wanted)); }
    // The frames from index `from` on.
    std::vector<CanFrame> since(std::size_t from) const {
        return {all.begin() + std::ptrdiff_t(std::min(from, all.size())), all.end()};
    }
    // The frames about one handle (session frames), in order.
    std::vector<CanFrame> onHandle(std::uint16_t handle, std::size_t from = 0) const {
        std::vector<CanFrame> result;
        for (const CanFrame& f : since(from))
            if (mcan::layoutOf(f.id) == mcan::Layout::Session && mcan::readSession(f.id).handle == handle)
                result.push_back(f);
        return result;
    }

    std::vector<CanFrame> all;

private:
    QObject context_;
};

// Fast clocks for tests: a poll every 20 ms, a new login attempt after 150 ms.
inline SimulatedMs1::Options fastMs1(std::uint32_t uid = 0x000204B3, std::string name = "KS MS1") {
    SimulatedMs1::Options options;
    options.identity.uid = uid;
    options.identity.name = std::move(name);
    options.timing.pollPeriod = std::chrono::milliseconds(20);
    options.timing.loginRetry = std::chrono::milliseconds(150);
    return options;
}

} // namespace stellwerk::sim::test
