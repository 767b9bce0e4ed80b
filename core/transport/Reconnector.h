#pragma once

#include "transport/TransportSettings.h"

#include <chrono>
#include <functional>

class QObject;
class QTimer;

namespace stellwerk::transport {

// Paces the connection attempts of a transport that keeps trying while open: a failed or lost
// connection is retried after a delay that doubles up to a maximum, and an attempt that hangs is given up.
class Reconnector {
public:
    // `attempt` starts one connection attempt; `attemptTimedOut` is called when it got no answer in time.
    // `owner` owns the timers (so that they move to another thread with their transport).
    Reconnector(QObject* owner, std::function<void()> attempt, std::function<void()> attemptTimedOut);

    void setTiming(const ReconnectTiming& timing) { timing_ = timing; }
    const ReconnectTiming& timing() const { return timing_; }

    // Makes the first attempt now.
    void start();
    // The current attempt succeeded. Returns true when it is a reconnection (an earlier attempt since
    // start() had succeeded too). The next failure is retried after the first delay again.
    bool connected();
    // The attempt failed or the connection was lost: the next attempt follows after the returned delay
    // (a loss reported again while waiting changes nothing).
    std::chrono::milliseconds lost();
    // No more attempts until start().
    void stop();

    // A retry is scheduled and not made yet.
    bool isWaiting() const;

private:
    void makeAttempt();

    std::function<void()> attempt_;
    ReconnectTiming timing_;
    QTimer* retryTimer_;
    QTimer* attemptTimer_;
    std::chrono::milliseconds nextDelay_{0};
    std::chrono::milliseconds scheduledDelay_{0};
    bool hasConnected_ = false;
};

} // namespace stellwerk::transport
