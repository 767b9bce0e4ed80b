#include "transport/Reconnector.h"

#include <QTimer>
#include <algorithm>

namespace stellwerk::transport {

Reconnector::Reconnector(QObject* owner, std::function<void()> attempt, std::function<void()> attemptTimedOut)
    : attempt_(std::move(attempt)), retryTimer_(new QTimer(owner)), attemptTimer_(new QTimer(owner)) {
    retryTimer_->setSingleShot(true);
    attemptTimer_->setSingleShot(true);
    QObject::connect(retryTimer_, &QTimer::timeout, owner, [this] { makeAttempt(); });
    QObject::connect(attemptTimer_, &QTimer::timeout, owner, std::move(attemptTimedOut));
}

void Reconnector::start() {
    stop();
    nextDelay_ = timing_.firstRetry;
    makeAttempt();
}

bool Reconnector::connected() {
    attemptTimer_->stop();
    nextDelay_ = timing_.firstRetry;
    const bool again = hasConnected_;
    hasConnected_ = true;
    return again;
}

// A loss reported again while the retry waits changes nothing.
std::chrono::milliseconds Reconnector::lost() {
    if (isWaiting())
        return scheduledDelay_;
    attemptTimer_->stop();
    scheduledDelay_ = std::max(nextDelay_, std::chrono::milliseconds{0});
    retryTimer_->start(scheduledDelay_);
    nextDelay_ = std::min(std::max(scheduledDelay_ * 2, std::chrono::milliseconds{1}), timing_.maxRetry);
    return scheduledDelay_;
}

void Reconnector::stop() {
    retryTimer_->stop();
    attemptTimer_->stop();
    hasConnected_ = false;
}

bool Reconnector::isWaiting() const {
    return retryTimer_->isActive();
}

// The timeout is armed before the attempt, which may succeed or fail before it returns.
void Reconnector::makeAttempt() {
    if (timing_.attemptTimeout.count() > 0)
        attemptTimer_->start(timing_.attemptTimeout);
    attempt_();
}

} // namespace stellwerk::transport
