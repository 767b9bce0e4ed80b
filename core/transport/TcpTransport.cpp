#include "transport/TcpTransport.h"

#include "transport/DurationText.h"
#include "transport/NetworkFraming.h"
#include "transport/TransportAddress.h"

#include <QSignalBlocker>
#include <QTcpSocket>

#if defined(Q_OS_UNIX)
#include <sys/socket.h>
#endif

namespace stellwerk::transport {

using can::CanFrame;

namespace {

// Makes the next close send a reset instead of delivering what is still buffered: the peer drops what
// it has not read (POSIX; elsewhere the close is an ordinary one).
void resetOnClose([[maybe_unused]] QTcpSocket& socket) {
#if defined(Q_OS_UNIX)
    if (socket.socketDescriptor() < 0)
        return;
    const linger immediately{1, 0};
    ::setsockopt(int(socket.socketDescriptor()), SOL_SOCKET, SO_LINGER, &immediately, sizeof immediately);
#endif
}

} // namespace

TcpTransport::TcpTransport(TcpSettings settings, QObject* parent)
    : Transport(parent), settings_(std::move(settings)), socket_(new QTcpSocket(this)),
      reconnector_(
          this, [this] { connectToStation(); },
          [this] {
              connectionLost(tr("no answer within %1").arg(durationText(settings_.reconnect.attemptTimeout)));
          }) {
    reconnector_.setTiming(settings_.reconnect);
    connect(socket_, &QTcpSocket::connected, this, &TcpTransport::onConnected);
    connect(socket_, &QTcpSocket::readyRead, this, &TcpTransport::onReadyRead);
    connect(socket_, &QTcpSocket::bytesWritten, this, &TcpTransport::onBytesWritten);
    connect(socket_, &QTcpSocket::disconnected, this,
            [this] { connectionLost(tr("the station closed the connection")); });
    connect(socket_, &QTcpSocket::errorOccurred, this, [this] { connectionLost(socket_->errorString()); });
}

void TcpTransport::open() {
    if (state() != State::Closed)
        return;
    setState(State::Connecting);
    reconnector_.start();
}

void TcpTransport::close() {
    if (state() == State::Closed)
        return;
    setState(State::Closed);
    reconnector_.stop();
    assembler_.clear();
    socket_->disconnectFromHost();
}

bool TcpTransport::resetConnection(const QString& reason) {
    if (state() != State::Connected)
        return false;
    {
        const QSignalBlocker quiet(socket_);
        resetOnClose(*socket_);
        socket_->abort();
    }
    connectionLost(reason);
    return true;
}

QString TcpTransport::description() const {
    return transportUrl(settings_);
}

std::size_t TcpTransport::writeFrames(std::span<const CanFrame> frames) {
    const QByteArray bytes = encodeFrames(frames);
    const bool written = socket_->write(bytes) == bytes.size();
    if (socket_->bytesToWrite() > BusyBytes)
        setWireBusy(true);
    return written ? frames.size() : 0;
}

// The peer reads again: frames that waited in the send queue follow.
void TcpTransport::onBytesWritten() {
    if (socket_->bytesToWrite() <= BusyBytes)
        setWireBusy(false);
}

// The old socket is dropped quietly: its last signals belong to a loss already handled.
void TcpTransport::connectToStation() {
    {
        const QSignalBlocker quiet(socket_);
        socket_->abort();
    }
    assembler_.clear();
    socket_->connectToHost(settings_.host, settings_.port);
}

void TcpTransport::onConnected() {
    socket_->setSocketOption(QAbstractSocket::LowDelayOption, 1);
    socket_->setSocketOption(QAbstractSocket::KeepAliveOption, 1);
    if (reconnector_.connected())
        countReconnect();
    setState(State::Connected);
}

// Everything that arrived goes out as one batch: one signal per read, whatever the frame rate.
void TcpTransport::onReadyRead() {
    const QByteArray bytes = socket_->readAll();
    std::vector<CanFrame> frames;
    frames.reserve(std::size_t(bytes.size()) / CanFrame::NetworkSize + 1);
    const std::size_t malformed = assembler_.feed(asBytes(bytes), frames);
    countMalformed(malformed, tr("sent %n frame(s) with a DLC above 8; left out", nullptr, int(malformed)));
    deliver(std::move(frames));
}

// The socket reports a loss twice (error, then disconnected): only the first one schedules a retry.
void TcpTransport::connectionLost(const QString& reason) {
    if (state() == State::Closed || reconnector_.isWaiting())
        return;
    if (socket_->bytesAvailable() > 0)
        onReadyRead();
    if (assembler_.pendingBytes() > 0)
        countMalformed(1, tr("connection ended inside a frame (%n byte(s) of 13)", nullptr,
                             int(assembler_.pendingBytes())));
    assembler_.clear();
    const auto delay = reconnector_.lost();
    reportConnectionLost(reason, delay);
    setState(State::Reconnecting);
}

} // namespace stellwerk::transport
