#include "transport/LoopbackTransport.h"

#include <QTimer>

namespace stellwerk::transport {

using can::CanFrame;

LoopbackTransport::LoopbackTransport(QString name, QObject* parent)
    : Transport(parent), name_(std::move(name)), deliveryTimer_(new QTimer(this)) {
    deliveryTimer_->setSingleShot(true);
    connect(deliveryTimer_, &QTimer::timeout, this, &LoopbackTransport::deliverArrived);
}

LoopbackTransport::~LoopbackTransport() {
    if (peer_ && state() != State::Closed)
        peer_->peerClosed();
}

void LoopbackTransport::join(LoopbackTransport& first, LoopbackTransport& second) {
    first.peer_ = &second;
    second.peer_ = &first;
}

void LoopbackTransport::open() {
    if (state() != State::Closed)
        return;
    hasConnected_ = false;
    const bool peerOpen = peer_ && peer_->state() != State::Closed;
    setState(peerOpen ? State::Connected : State::Connecting);
    hasConnected_ = peerOpen;
    if (peerOpen)
        peer_->peerOpened();
}

void LoopbackTransport::close() {
    if (state() == State::Closed)
        return;
    deliveryTimer_->stop();
    arrived_.clear();
    setState(State::Closed);
    if (peer_)
        peer_->peerClosed();
}

QString LoopbackTransport::description() const {
    return QStringLiteral("loopback://%1").arg(name_);
}

std::size_t LoopbackTransport::writeFrames(std::span<const CanFrame> frames) {
    if (!peer_ || peer_->state() == State::Closed)
        return 0;
    peer_->arrive(frames);
    return frames.size();
}

void LoopbackTransport::peerOpened() {
    if (state() != State::Connecting && state() != State::Reconnecting)
        return;
    if (hasConnected_)
        countReconnect();
    hasConnected_ = true;
    setState(State::Connected);
}

void LoopbackTransport::peerClosed() {
    if (state() == State::Connected)
        setState(State::Reconnecting);
}

void LoopbackTransport::arrive(std::span<const CanFrame> frames) {
    arrived_.insert(arrived_.end(), frames.begin(), frames.end());
    if (!deliveryTimer_->isActive())
        deliveryTimer_->start(0);
}

void LoopbackTransport::deliverArrived() {
    std::vector<CanFrame> frames;
    frames.swap(arrived_);
    deliver(std::move(frames));
}

} // namespace stellwerk::transport
