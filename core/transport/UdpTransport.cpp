#include "transport/UdpTransport.h"

#include "transport/DurationText.h"
#include "transport/NetworkFraming.h"
#include "transport/TransportAddress.h"

#include <QHostInfo>
#include <QSignalBlocker>
#include <QUdpSocket>
#include <algorithm>

namespace stellwerk::transport {

using can::CanFrame;

namespace {

// A CS2 speaks IPv4; of several addresses for a name the first IPv4 one is taken.
QHostAddress preferIpv4(const QList<QHostAddress>& addresses) {
    const auto ipv4 = std::find_if(addresses.begin(), addresses.end(), [](const QHostAddress& address) {
        return address.protocol() == QAbstractSocket::IPv4Protocol;
    });
    return ipv4 != addresses.end() ? *ipv4 : addresses.value(0);
}

} // namespace

UdpTransport::UdpTransport(UdpSettings settings, QObject* parent)
    : Transport(parent), settings_(std::move(settings)), socket_(new QUdpSocket(this)),
      reconnector_(
          this, [this] { resolveStation(); },
          [this] {
              attemptFailed(tr("no address for %1 within %2")
                                .arg(settings_.host, durationText(settings_.reconnect.attemptTimeout)));
          }) {
    reconnector_.setTiming(settings_.reconnect);
    connect(socket_, &QUdpSocket::readyRead, this, &UdpTransport::onReadyRead);
}

UdpTransport::~UdpTransport() {
    stopLookup();
}

void UdpTransport::open() {
    if (state() != State::Closed)
        return;
    setState(State::Connecting);
    reconnector_.start();
}

void UdpTransport::close() {
    if (state() == State::Closed)
        return;
    setState(State::Closed);
    reconnector_.stop();
    stopLookup();
    const QSignalBlocker quiet(socket_);
    socket_->abort();
}

QString UdpTransport::description() const {
    return transportUrl(settings_);
}

std::uint16_t UdpTransport::boundPort() const {
    return socket_->localPort();
}

// One datagram per frame: a CS2 drops datagrams that are not exactly 13 bytes.
std::size_t UdpTransport::writeFrames(std::span<const CanFrame> frames) {
    std::size_t written = 0;
    for (const CanFrame& frame : frames) {
        const auto bytes = frame.toNetwork();
        const auto sent = socket_->writeDatagram(reinterpret_cast<const char*>(bytes.data()),
                                                 qint64(bytes.size()), station_, settings_.remotePort);
        reportSendFailure(sent != qint64(bytes.size()));
        written += sent == qint64(bytes.size()) ? 1 : 0;
    }
    return written;
}

void UdpTransport::resolveStation() {
    stopLookup();
    const QHostAddress address(settings_.host);
    if (!address.isNull()) {
        station_ = address;
        return bindSocket();
    }
    lookupId_ = QHostInfo::lookupHost(settings_.host, this, &UdpTransport::onLookup);
}

void UdpTransport::onLookup(const QHostInfo& info) {
    lookupId_ = -1;
    if (info.error() != QHostInfo::NoError || info.addresses().isEmpty())
        return attemptFailed(tr("cannot find %1: %2").arg(settings_.host, info.errorString()));
    station_ = preferIpv4(info.addresses());
    bindSocket();
}

// Other programs on this computer may listen to the station's broadcasts too: the port is shared.
void UdpTransport::bindSocket() {
    {
        const QSignalBlocker quiet(socket_);
        socket_->abort();
    }
    const auto mode = QAbstractSocket::ShareAddress | QAbstractSocket::ReuseAddressHint;
    if (!socket_->bind(settings_.localAddress, settings_.localPort, mode))
        return attemptFailed(
            tr("cannot receive on port %1: %2").arg(settings_.localPort).arg(socket_->errorString()));
    if (reconnector_.connected())
        countReconnect();
    setState(State::Connected);
}

void UdpTransport::attemptFailed(const QString& reason) {
    if (state() == State::Closed || reconnector_.isWaiting())
        return;
    stopLookup();
    const auto delay = reconnector_.lost();
    reportConnectionLost(reason, delay);
    setState(State::Reconnecting);
}

// All datagrams waiting now go out as one batch.
void UdpTransport::onReadyRead() {
    std::vector<CanFrame> frames;
    while (socket_->hasPendingDatagrams() && readDatagram(frames)) {
    }
    deliver(std::move(frames));
}

bool UdpTransport::readDatagram(std::vector<CanFrame>& frames) {
    datagram_.resize(std::max<qint64>(socket_->pendingDatagramSize(), 0));
    QHostAddress sender;
    quint16 senderPort = 0;
    const qint64 size = socket_->readDatagram(datagram_.data(), datagram_.size(), &sender, &senderPort);
    if (size < 0) {
        emit problem(tr("%1: cannot receive: %2").arg(description(), socket_->errorString()));
        return false;
    }
    const DatagramContent content = decodeDatagram(asBytes(datagram_).first(std::size_t(size)), frames);
    if (!content.wholeFrames || content.malformed > 0)
        countBadDatagram(content, std::size_t(size),
                         QStringLiteral("%1:%2").arg(sender.toString()).arg(senderPort));
    return true;
}

void UdpTransport::countBadDatagram(const DatagramContent& content, std::size_t size, const QString& sender) {
    if (!content.wholeFrames)
        return countMalformed(
            1, tr("datagram of %n byte(s) from %1 is not a multiple of 13 bytes; dropped", nullptr, int(size))
                   .arg(sender));
    countMalformed(
        content.malformed,
        tr("%n frame(s) from %1 with a DLC above 8; left out", nullptr, int(content.malformed)).arg(sender));
}

void UdpTransport::stopLookup() {
    if (lookupId_ >= 0)
        QHostInfo::abortHostLookup(lookupId_);
    lookupId_ = -1;
}

// Reports the first failed datagram of a run of failures, not each one.
void UdpTransport::reportSendFailure(bool failed) {
    if (failed && !sendFailing_)
        emit problem(tr("%1: cannot send: %2").arg(description(), socket_->errorString()));
    sendFailing_ = failed;
}

} // namespace stellwerk::transport
