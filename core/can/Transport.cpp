#include "can/Transport.h"

#include <QLoggingCategory>
#include <QMetaMethod>

namespace stellwerk::can {

namespace {
Q_LOGGING_CATEGORY(lcTransport, "stellwerk.can")
}

using cs2::CanFrame;

Transport::Transport(QObject* parent)
    : QObject(parent), queue_(this, [this](std::span<const CanFrame> frames) { write(frames); }) {}

bool Transport::send(const CanFrame& frame) {
    return sendBatch(std::span(&frame, 1)) == 1;
}

std::size_t Transport::sendBatch(std::span<const CanFrame> frames) {
    const std::size_t accepted = state_ == State::Closed ? 0 : queue_.push(frames);
    counters_.dropped += frames.size() - accepted;
    return accepted;
}

void Transport::setState(State state) {
    if (state_ == state)
        return;
    state_ = state;
    if (state == State::Closed)
        discardWaiting();
    queue_.setWritable(state == State::Connected);
    emit stateChanged(state);
}

void Transport::discardWaiting() {
    const std::size_t discarded = queue_.discard();
    if (discarded == 0)
        return;
    counters_.dropped += discarded;
    emit problem(tr("%1: closed with %n frame(s) not sent", nullptr, int(discarded)).arg(description()));
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
    emit problem(tr("%1; trying again in %2 ms").arg(failure).arg(retryIn.count()));
}

} // namespace stellwerk::can
