#include "transport/Transport.h"

#include "transport/DurationText.h"

#include <QLoggingCategory>
#include <QMetaMethod>
#include <algorithm>

namespace stellwerk::transport {

namespace {
Q_LOGGING_CATEGORY(lcTransport, "stellwerk.can")
}

using can::CanFrame;

Transport::Transport(QObject* parent)
    : QObject(parent), queue_(this, [this](std::span<const CanFrame> frames) { write(frames); }) {}

bool Transport::send(const CanFrame& frame, SendTicket ticket) {
    return sendBatch(std::span(&frame, 1), ticket) == 1;
}

std::size_t Transport::sendBatch(std::span<const CanFrame> frames, SendTicket ticket) {
    const std::size_t acceptable = refusesFrames() ? 0 : acceptableFrames(frames);
    const std::size_t accepted = acceptable == 0 ? 0 : queue_.push(frames.first(acceptable), ticket);
    counters_.dropped += frames.size() - accepted;
    return accepted;
}

// The frames up to the first standard frame, when the wire cannot carry those (reported as a problem).
std::size_t Transport::acceptableFrames(std::span<const CanFrame> frames) {
    if (carriesStandardFrames())
        return frames.size();
    const auto standard =
        std::find_if(frames.begin(), frames.end(), [](const CanFrame& f) { return !f.extended; });
    if (standard != frames.end())
        emit problem(
            tr("%1: refused a standard (11-bit) CAN frame with id 0x%2: a CS2 gateway carries 29-bit "
               "frames only (use a CAN adapter for this bus)")
                .arg(description())
                .arg(standard->id, 3, 16, QLatin1Char('0')));
    return std::size_t(standard - frames.begin());
}

std::size_t Transport::withdraw(SendTicket ticket) {
    const std::size_t withdrawn = queue_.withdraw(ticket);
    counters_.dropped += withdrawn;
    return withdrawn;
}

bool Transport::resetConnection(const QString&) {
    return false;
}

void Transport::setState(State state) {
    if (state_ == state)
        return;
    const bool lost = state_ == State::Connected;
    state_ = state;
    if (state == State::Closed)
        lostOnce_ = false;
    else if (lost)
        lostOnce_ = true;
    if (state == State::Closed || lost)
        discardWaiting(state == State::Closed);
    wireBusy_ = false;
    queue_.setWritable(state == State::Connected);
    emit stateChanged(state);
}

void Transport::setWireBusy(bool busy) {
    if (wireBusy_ == busy)
        return;
    wireBusy_ = busy;
    queue_.setWritable(state_ == State::Connected && !busy);
}

void Transport::discardWaiting(bool closed) {
    const std::size_t discarded = queue_.discard();
    if (discarded == 0)
        return;
    counters_.dropped += discarded;
    emit problem(
        closed
            ? tr("%1: closed with %n frame(s) not sent", nullptr, int(discarded)).arg(description())
            : tr("%1: connection lost with %n frame(s) not sent; they are dropped", nullptr, int(discarded))
                  .arg(description()));
}

void Transport::deliver(std::vector<CanFrame>&& frames) {
    if (frames.empty())
        return;
    counters_.framesIn += frames.size();
    emit framesReceived(frames);
}

void Transport::countMalformed(std::size_t count, const QString& what) {
    if (count == 0)
        return;
    counters_.malformed += count;
    qCWarning(lcTransport).noquote() << description() << what;
}

void Transport::write(std::span<const CanFrame> frames) {
    if (state_ != State::Connected) { // a loss reported from inside an earlier write of this block
        counters_.dropped += frames.size();
        return;
    }
    const std::size_t written = writeFrames(frames);
    counters_.framesOut += written;
    counters_.dropped += frames.size() - written;
    reportSent(frames.first(written));
}

// Copies the frames only when someone listens: a flood of writes costs nothing without a bus monitor.
void Transport::reportSent(std::span<const CanFrame> frames) {
    static const QMetaMethod sent = QMetaMethod::fromSignal(&Transport::framesSent);
    if (frames.empty() || !isSignalConnected(sent))
        return;
    emit framesSent(std::vector<CanFrame>(frames.begin(), frames.end()));
}

void Transport::reportConnectionLost(const QString& reason, std::chrono::milliseconds retryIn) {
    const QString failure = QStringLiteral("%1: %2").arg(description(), reason);
    emit connectionFailed(failure);
    emit problem(tr("%1; trying again in %2").arg(failure, durationText(retryIn)));
}

} // namespace stellwerk::transport
