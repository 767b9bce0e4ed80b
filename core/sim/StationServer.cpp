#include "sim/StationServer.h"

#include "sim/SimulatedBus.h"
#include "sim/SimulatedStation.h"
#include "transport/CanBusTransport.h"
#include "transport/NetworkFraming.h"

#include <QLoggingCategory>
#include <QNetworkDatagram>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTimer>
#include <QUdpSocket>

namespace stellwerk::sim {

namespace {

Q_LOGGING_CATEGORY(serverLog, "stellwerk.sim.server")

QString endpoint(const QHostAddress& address, std::uint16_t port) {
    return address.toString() + ':' + QString::number(port);
}

} // namespace

StationServer::StationServer(SimulatedStation& station, StationServerSettings settings, QObject* parent)
    : QObject(parent), station_(station), settings_(std::move(settings)) {
    connect(&station_, &SimulatedStation::framesEmitted, this,
            [this](const std::vector<can::CanFrame>& frames) {
                counters_.framesOut += frames.size();
                broadcast(frames, std::nullopt);
            });
}

StationServer::StationServer(SimulatedStation& station, SimulatedBus& bus, StationServerSettings settings,
                             QObject* parent)
    : QObject(parent), station_(station), bus_(&bus), settings_(std::move(settings)) {
    connect(&bus, &SimulatedBus::framesCarried, this, [this](const std::vector<can::CanFrame>& frames) {
        counters_.framesOut += frames.size();
        broadcast(frames, std::nullopt);
    });
}

StationServer::~StationServer() {
    for (auto& [socket, assembler] : clients_)
        socket->disconnect(this); // closing them must not call back into a half-destroyed server
}

bool StationServer::listen() {
    if (settings_.udp && !listenUdp())
        return false;
    if (settings_.tcp && !listenTcp())
        return false;
    if (settings_.canBus)
        openCanBus();
    return true;
}

bool StationServer::listenUdp() {
    udp_ = new QUdpSocket(this);
    if (!udp_->bind(settings_.listenAddress, settings_.udpPort)) {
        error_ = "UDP port " + QString::number(settings_.udpPort) + ": " + udp_->errorString();
        return false;
    }
    connect(udp_, &QUdpSocket::readyRead, this, &StationServer::readDatagrams);
    return true;
}

bool StationServer::listenTcp() {
    tcp_ = new QTcpServer(this);
    if (!tcp_->listen(settings_.listenAddress, settings_.tcpPort)) {
        error_ = "TCP port " + QString::number(settings_.tcpPort) + ": " + tcp_->errorString();
        return false;
    }
    connect(tcp_, &QTcpServer::newConnection, this, &StationServer::acceptClients);
    return true;
}

void StationServer::openCanBus() {
    canBus_ = new transport::CanBusTransport(*settings_.canBus, this);
    connect(canBus_, &transport::Transport::framesReceived, this,
            [this](const std::vector<can::CanFrame>& frames) { arrived(frames, {Origin::Kind::Can}); });
    connect(canBus_, &transport::Transport::problem, this, &StationServer::problem);
    canBus_->open();
}

std::uint16_t StationServer::udpPort() const {
    return udp_ ? udp_->localPort() : 0;
}

std::uint16_t StationServer::tcpPort() const {
    return tcp_ ? tcp_->serverPort() : 0;
}

QStringList StationServer::listeners() const {
    QStringList result;
    if (udp_)
        result << "udp " + endpoint(settings_.listenAddress, udpPort()) + " -> " +
                      endpoint(settings_.udpReplyHost, settings_.udpReplyPort);
    if (tcp_)
        result << "tcp " + endpoint(settings_.listenAddress, tcpPort());
    if (canBus_)
        result << "can " + canBus_->description();
    return result;
}

// A CS2 takes datagrams of n x 13 bytes; anything else is counted and dropped.
void StationServer::readDatagrams() {
    while (!stalled_ && udp_->hasPendingDatagrams()) { // a stalled station leaves them in its socket
        const QNetworkDatagram datagram = udp_->receiveDatagram();
        std::vector<can::CanFrame> frames;
        const transport::DatagramContent content =
            transport::decodeDatagram(transport::asBytes(datagram.data()), frames);
        if (!content.wholeFrames) {
            ++counters_.malformedDatagrams;
            qCInfo(serverLog) << "dropped a UDP datagram of" << datagram.data().size() << "bytes from"
                              << datagram.senderAddress().toString() << "(not n x 13 bytes)";
        }
        counters_.malformedFrames += content.malformed;
        received(frames, {Origin::Kind::Udp});
    }
}

void StationServer::acceptClients() {
    while (QTcpSocket* socket = tcp_->nextPendingConnection()) {
        // A frame goes out at once, as the station sends it (without this, an S88 event right after an
        // answer waited up to 40 ms for the client's delayed acknowledgement).
        socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        clients_.emplace(socket, transport::FrameAssembler{});
        ++counters_.tcpConnections;
        connect(socket, &QTcpSocket::readyRead, this, [this, socket] { readClient(socket); });
        connect(socket, &QTcpSocket::disconnected, this, [this, socket] { dropClient(socket); });
        if (settings_.announcePowerToNewClients) // once the client's side saw the connection
            QTimer::singleShot(0, this, [this] { station_.announcePower(); });
        emit tcpClientsChanged(int(clients_.size()));
    }
}

// TCP is a byte stream: the client's assembler cuts it into frames whatever the segmentation.
void StationServer::readClient(QTcpSocket* socket) {
    const auto client = clients_.find(socket);
    if (client == clients_.end())
        return;
    const QByteArray bytes = socket->readAll();
    std::vector<can::CanFrame> frames;
    counters_.malformedFrames += client->second.feed(transport::asBytes(bytes), frames);
    arrived(std::move(frames), {Origin::Kind::Tcp, socket});
}

void StationServer::dropClient(QTcpSocket* socket) {
    if (clients_.count(socket) && stalled_)
        readClient(socket); // what it sent is read when the station wakes, as from a kernel's buffer
    for (auto& [frames, origin] : heldIn_)
        if (origin.socket == socket)
            origin.socket = nullptr;
    if (clients_.erase(socket) == 0)
        return;
    socket->deleteLater();
    emit tcpClientsChanged(int(clients_.size()));
}

void StationServer::arrived(std::vector<can::CanFrame> frames, Origin origin) {
    if (stalled_) {
        if (!frames.empty())
            heldIn_.emplace_back(std::move(frames), origin);
        return;
    }
    received(frames, origin);
}

void StationServer::stall() {
    stalled_ = true;
    if (tcp_)
        tcp_->pauseAccepting();
}

void StationServer::wake() {
    if (!stalled_)
        return;
    stalled_ = false;
    const std::vector<can::CanFrame> out = std::exchange(heldOut_, {});
    if (!out.empty())
        broadcast(out, std::nullopt);
    for (auto& [frames, origin] : std::exchange(heldIn_, {}))
        received(frames, origin);
    if (udp_)
        readDatagrams();
    if (tcp_) {
        tcp_->resumeAccepting();
        acceptClients();
    }
}

void StationServer::received(const std::vector<can::CanFrame>& frames, Origin origin) {
    if (frames.empty())
        return;
    counters_.framesIn += frames.size();
    broadcast(frames, origin);
    if (bus_) {
        bus_->putFromOutside(frames);
        return;
    }
    for (const can::CanFrame& frame : frames)
        station_.receive(frame);
}

void StationServer::broadcast(std::span<const can::CanFrame> frames, const std::optional<Origin>& except) {
    if (stalled_) {
        heldOut_.insert(heldOut_.end(), frames.begin(), frames.end());
        return;
    }
    const auto from = [&except](Origin::Kind kind) { return except && except->kind == kind; };
    if (udp_ && !from(Origin::Kind::Udp))
        sendUdp(frames);
    if (canBus_ && !from(Origin::Kind::Can))
        canBus_->sendBatch(frames);
    if (clients_.empty())
        return;
    const QByteArray bytes = transport::encodeFrames(frames);
    for (auto& [socket, assembler] : clients_)
        if (!except || except->socket != socket)
            socket->write(bytes);
}

// One frame per datagram, as a CS2 sends them.
void StationServer::sendUdp(std::span<const can::CanFrame> frames) {
    for (const can::CanFrame& frame : frames)
        udp_->writeDatagram(transport::encodeFrames(std::span(&frame, 1)), settings_.udpReplyHost,
                            settings_.udpReplyPort);
}

} // namespace stellwerk::sim
