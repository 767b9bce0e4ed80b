#include "transport/SendQueue.h"

#include <QTimer>
#include <algorithm>
#include <vector>

namespace stellwerk::transport {

using can::CanFrame;

SendQueue::SendQueue(QObject* owner, Writer writer) : writer_(std::move(writer)), timer_(new QTimer(owner)) {
    timer_->setSingleShot(true);
    timer_->setTimerType(Qt::PreciseTimer);
    QObject::connect(timer_, &QTimer::timeout, owner, [this] { pump(); });
}

std::size_t SendQueue::push(std::span<const CanFrame> frames, SendTicket ticket) {
    if (writable_ && waiting_.empty() && !paced()) {
        writer_(frames);
        return frames.size();
    }
    std::size_t accepted = 0;
    for (const CanFrame& frame : frames) {
        if (writable_ && waiting_.empty() && gapElapsed())
            writeOne(frame);
        else if (waiting_.size() < limit_)
            waiting_.push_back({frame, ticket});
        else
            break;
        ++accepted;
    }
    pump();
    return accepted;
}

std::size_t SendQueue::withdraw(SendTicket ticket) {
    if (ticket == 0)
        return 0;
    const auto removed = std::erase_if(waiting_, [ticket](const Waiting& w) { return w.ticket == ticket; });
    if (waiting_.empty())
        timer_->stop();
    return removed;
}

void SendQueue::setWritable(bool writable) {
    writable_ = writable;
    if (writable)
        pump();
    else
        timer_->stop();
}

std::size_t SendQueue::discard() {
    const std::size_t count = waiting_.size();
    waiting_.clear();
    timer_->stop();
    return count;
}

void SendQueue::setPacing(std::chrono::milliseconds gap) {
    gap_ = std::max(gap, std::chrono::milliseconds{0});
    timer_->stop();
    pump();
}

bool SendQueue::gapElapsed() const {
    return !paced() || !sinceLastWrite_.isValid() ||
           std::chrono::nanoseconds(sinceLastWrite_.nsecsElapsed()) >= std::chrono::nanoseconds(gap_);
}

int SendQueue::msUntilGapElapsed() const {
    const auto left =
        std::chrono::nanoseconds(gap_) - std::chrono::nanoseconds(sinceLastWrite_.nsecsElapsed());
    return int(std::max<std::int64_t>(0, std::chrono::ceil<std::chrono::milliseconds>(left).count()));
}

// Writes what may go now; when frames must wait for the gap, the timer comes back for them.
void SendQueue::pump() {
    if (!writable_ || waiting_.empty() || timer_->isActive())
        return;
    if (!paced())
        return writeAllWaiting();
    if (gapElapsed()) {
        const CanFrame frame = waiting_.front().frame;
        waiting_.pop_front();
        writeOne(frame);
    }
    if (writable_ && !waiting_.empty() && !timer_->isActive())
        timer_->start(msUntilGapElapsed());
}

void SendQueue::writeAllWaiting() {
    std::vector<CanFrame> frames;
    frames.reserve(waiting_.size());
    for (const Waiting& w : waiting_)
        frames.push_back(w.frame);
    waiting_.clear();
    writer_(frames);
}

void SendQueue::writeOne(const CanFrame& frame) {
    sinceLastWrite_.start();
    writer_(std::span(&frame, 1));
}

} // namespace stellwerk::transport
