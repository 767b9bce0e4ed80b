#pragma once

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEvent>
#include <QEventLoop>
#include <QTimer>
#include <functional>

namespace stellwerk::support {

// Runs the event loop until the condition holds or the time is up. Unlike QTest::qWaitFor, which sleeps
// 10 ms between passes, it handles each event as it comes, so a conversation of many exchanges (a start-up,
// an MS1's upgrade on the simulated bus) takes what the sockets take. A ticking timer wakes it to look at
// the clock; objects given to deleteLater() go on the way.
inline bool runEventsUntil(const std::function<bool()>& condition, int timeoutMs) {
    QElapsedTimer clock;
    clock.start();
    QTimer tick;
    tick.start(10);
    while (!condition()) {
        if (clock.elapsed() >= timeoutMs)
            return condition();
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
        QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
    }
    return true;
}

} // namespace stellwerk::support
