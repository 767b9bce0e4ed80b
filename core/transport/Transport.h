#pragma once

#include "can/CanFrame.h"
#include "transport/SendQueue.h"

#include <QObject>
#include <QString>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace stellwerk::transport {

// What a transport has seen and done since it was created, for the status bar and for tests.
struct TransportCounters {
    std::uint64_t framesIn = 0;   // frames delivered to the application
    std::uint64_t framesOut = 0;  // frames handed to the wire
    std::uint64_t malformed = 0;  // input that was not a frame (wrong datagram size, DLC above 8, ...)
    std::uint64_t dropped = 0;    // frames lost: refused while closed, queue overflow, failed writes
    std::uint64_t reconnects = 0; // connections made again after a loss (the first one after open() is not)
};

// One way to reach a station's CAN bus (UDP gateway, TCP, a QCanBus device, an in-process pipe):
// frames out, batches of frames in, connection state and counters. Lives on the thread that uses it.
class Transport : public QObject {
    Q_OBJECT

public:
    enum class State { Closed, Connecting, Connected, Reconnecting };
    Q_ENUM(State)

    explicit Transport(QObject* parent = nullptr);

    // Starts connecting (and keeps reconnecting with back-off until close()).
    virtual void open() = 0;
    // Stops; frames still waiting for the wire are discarded and counted as dropped.
    virtual void close() = 0;
    // Ends the current connection so that nothing written to it can still be read by the peer, and makes
    // it again (after the usual back-off). For a station that stopped answering: a stream transport
    // (TCP) would otherwise hand it, when it wakes up, the commands it did not read in time. Transports
    // without such a buffer (UDP datagrams, a CAN bus) do nothing; returns whether a connection ended.
    virtual bool resetConnection(const QString& reason);

    // Hands a frame to the wire: at once when connected, otherwise (or while pacing or a busy wire holds
    // it back) from the send queue, in order. Returns false when the frame is refused: the transport is
    // closed, the frame is a standard one the wire cannot carry, the connection was lost and is not back yet,
    // or the queue is full; the frame is then counted as dropped. Only before the first connection do frames
    // wait for the wire: once a connection was made and lost, what was said before the loss is discarded (a
    // station that comes back must not receive commands that were given up meanwhile) and new frames are
    // refused until it is back.
    bool send(const can::CanFrame& frame, SendTicket ticket = 0);
    // Sends frames in order, as one block where the wire allows it. Returns how many were accepted; the
    // rest (from the first refused one on) are counted as dropped. `ticket` marks them for withdraw().
    std::size_t sendBatch(std::span<const can::CanFrame> frames, SendTicket ticket = 0);
    // Takes back the frames with this ticket that have not reached the wire yet (counted as dropped);
    // returns how many. Frames already written are not affected.
    std::size_t withdraw(SendTicket ticket);
    // Whether the wire carries standard (11-bit) frames. The CS2 gateways' 13-byte network form (UDP, TCP)
    // has room for 29-bit identifiers only: send() refuses a standard frame there, reporting a problem.
    virtual bool carriesStandardFrames() const { return true; }
    // Whether send() would refuse now because the connection was lost and is not back.
    bool refusesFrames() const {
        return state_ == State::Closed || (state_ != State::Connected && lostOnce_);
    }

    State state() const { return state_; }
    const TransportCounters& counters() const { return counters_; }
    // A short human-readable description: "udp://192.168.1.2:15731", "can://socketcan/can0".
    virtual QString description() const = 0;

    // Minimum gap between two frames written to the wire (a Gleisbox needs about 10 ms); 0 = none.
    void setPacing(std::chrono::milliseconds gap) { queue_.setPacing(gap); }
    std::chrono::milliseconds pacing() const { return queue_.pacing(); }
    // How many frames may wait for the wire (while not connected, or held back by pacing).
    void setQueueLimit(std::size_t limit) { queue_.setLimit(limit); }
    std::size_t queueLimit() const { return queue_.limit(); }
    std::size_t queuedFrames() const { return queue_.size(); }

signals:
    // Frames that arrived, in order; one signal per read, never one per frame of a burst.
    void framesReceived(const std::vector<stellwerk::can::CanFrame>& frames);
    // Frames the wire took, in order, after pacing: one signal per block written (one frame at a time
    // while pacing spaces them out). Frames refused or still waiting are not in it.
    void framesSent(const std::vector<stellwerk::can::CanFrame>& frames);
    void stateChanged(stellwerk::transport::Transport::State state);
    // Something a person should see (connection refused, interface vanished, ...).
    void problem(const QString& message);
    // The connection failed or was lost: "<description>: <reason>", without the retry plan that the
    // problem() sent right after it adds. For callers that do not retry (the command line).
    void connectionFailed(const QString& reason);

protected:
    // Connected lets waiting frames go to the wire; Closed, and leaving Connected, discard them (counted
    // as dropped).
    void setState(State state);
    // The wire takes no more for now (a TCP peer that does not read): frames wait in the send queue,
    // where they can still be withdrawn, instead of piling up in the socket.
    void setWireBusy(bool busy);
    bool wireBusy() const { return wireBusy_; }
    // Puts frames on the wire; called only while Connected. Returns how many the wire took; the rest are
    // counted as dropped.
    virtual std::size_t writeFrames(std::span<const can::CanFrame> frames) = 0;
    // Hands received frames to the application as one batch (nothing happens for an empty batch).
    void deliver(std::vector<can::CanFrame>&& frames);
    // Counts input that was not a frame and logs what it was.
    void countMalformed(std::size_t count, const QString& what);
    void countReconnect() { ++counters_.reconnects; }
    // Reports a failed or lost connection that will be tried again after `retryIn`.
    void reportConnectionLost(const QString& reason, std::chrono::milliseconds retryIn);

private:
    void write(std::span<const can::CanFrame> frames);
    std::size_t acceptableFrames(std::span<const can::CanFrame> frames);
    void reportSent(std::span<const can::CanFrame> frames);
    void discardWaiting(bool closed);

    State state_ = State::Closed;
    bool lostOnce_ = false; // a connection was made and lost since open()
    bool wireBusy_ = false;
    TransportCounters counters_;
    SendQueue queue_;
};

} // namespace stellwerk::transport
