#pragma once

#include "can/CanFrame.h"

#include <QElapsedTimer>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <span>

class QObject;
class QTimer;

namespace stellwerk::transport {

// Marks the frames of one command in the queue, so that they can be withdrawn while they still wait
// (0 = frames nobody withdraws).
using SendTicket = std::uint64_t;

// Frames on their way to the wire: they wait (up to a limit) while the wire is away or busy, and are
// spaced out when a minimum gap is set, because a Gleisbox loses frames that come too close. Order is
// always kept. Frames that still wait can be withdrawn by their ticket: a command given up is never
// written later.
class SendQueue {
public:
    using Writer = std::function<void(std::span<const can::CanFrame>)>;
    static constexpr std::size_t DefaultLimit = 1000;

    // `owner` owns the pacing timer (so that it moves to another thread with its transport).
    SendQueue(QObject* owner, Writer writer);

    // Appends frames, writing at once what the wire and the gap allow. Returns how many were accepted:
    // a full queue refuses the rest.
    std::size_t push(std::span<const can::CanFrame> frames, SendTicket ticket = 0);
    // Removes the waiting frames with this ticket (not 0); returns how many there were.
    std::size_t withdraw(SendTicket ticket);
    // The wire is (or is no longer) there; when it comes back, what waits is written.
    void setWritable(bool writable);
    bool isWritable() const { return writable_; }
    // Forgets everything that waits; returns how many frames that were.
    std::size_t discard();

    std::size_t size() const { return waiting_.size(); }
    void setLimit(std::size_t limit) { limit_ = limit; }
    std::size_t limit() const { return limit_; }
    void setPacing(std::chrono::milliseconds gap);
    std::chrono::milliseconds pacing() const { return gap_; }

private:
    bool paced() const { return gap_.count() > 0; }
    bool gapElapsed() const;
    int msUntilGapElapsed() const;
    void pump();
    void writeAllWaiting();
    void writeOne(const can::CanFrame& frame);

    struct Waiting {
        can::CanFrame frame;
        SendTicket ticket = 0;
    };

    Writer writer_;
    QTimer* timer_;
    std::deque<Waiting> waiting_;
    std::size_t limit_ = DefaultLimit;
    std::chrono::milliseconds gap_{0};
    bool writable_ = false;
    QElapsedTimer sinceLastWrite_;
};

} // namespace stellwerk::transport
