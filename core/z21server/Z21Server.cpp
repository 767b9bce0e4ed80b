#include "z21server/Z21Server.h"

#include "model/Railway.h"
#include "model/Z21Addresses.h"
#include "z21/ReplyCodec.h"
#include "z21/RequestCodec.h"

#include <QNetworkDatagram>
#include <QTimer>
#include <QUdpSocket>
#include <algorithm>
#include <span>

namespace stellwerk::z21server {

Z21Server::Z21Server(model::Z21Addresses& addresses, Z21ServerOptions options, QObject* parent)
    : QObject(parent), addresses_(addresses), options_(std::move(options)), socket_(new QUdpSocket(this)),
      silenceTimer_(new QTimer(this)), follower_(railwayChanges()) {
    clock_.start();
    connect(socket_, &QUdpSocket::readyRead, this, &Z21Server::readDatagrams);
    const auto tick =
        std::clamp(options_.silence / 4, std::chrono::milliseconds(20), std::chrono::milliseconds(1000));
    silenceTimer_->setInterval(tick);
    connect(silenceTimer_, &QTimer::timeout, this, &Z21Server::dropSilent);
}

Z21Server::~Z21Server() = default;

bool Z21Server::listen() {
    if (!socket_->bind(options_.address, options_.port))
        return false;
    silenceTimer_->start();
    return true;
}

QString Z21Server::errorString() const {
    return socket_->errorString();
}

quint16 Z21Server::port() const {
    return socket_->localPort();
}

void Z21Server::setRailway(model::Railway* railway) {
    if (railway_ == railway)
        return;
    railway_ = railway;
    z21Railway_ = railway ? std::make_unique<Z21Railway>(*railway, addresses_) : nullptr;
    if (z21Railway_)
        z21Railway_->coverLocomotives();
    follower_.follow(railway);
    powerChanged();
}

model::RailwayFollower::Changes Z21Server::railwayChanges() {
    model::RailwayFollower::Changes changes;
    changes.loaded = [this] {
        if (z21Railway_)
            z21Railway_->coverLocomotives();
    };
    changes.locomotives = [this](const QList<quint32>& locIds) { locosChanged(locIds); };
    changes.accessories = [this](const QList<qint64>& numbers) { turnoutsChanged(numbers); };
    changes.addresses = changes.accessories;
    changes.power = [this] { powerChanged(); };
    changes.takenOver = [this](quint32 locId, const QString& from, const QString& to) {
        takenOver(locId, from, to);
    };
    changes.gone = [this] {
        z21Railway_.reset();
        powerChanged();
    };
    return changes;
}

void Z21Server::stopAll() {
    for (const auto& [name, client] : clients_.all())
        if (railway_)
            railway_->throttlePort().stopDrivenBy(name);
    clients_.all().clear();
}

bool Z21Server::allows(const QHostAddress& from) const {
    return options_.allowedClients.isEmpty() ||
           std::any_of(options_.allowedClients.cbegin(), options_.allowedClients.cend(),
                       [&from](const QHostAddress& allowed) { return allowed.isEqual(from); });
}

bool Z21Server::dropClient(const QString& client) {
    const std::optional<Z21Client> gone = clients_.remove(client);
    if (!gone)
        return false;
    goAway(*gone, Z21Event::Kind::Dropped);
    return true;
}

void Z21Server::readDatagrams() {
    while (socket_->hasPendingDatagrams()) {
        const QNetworkDatagram datagram = socket_->receiveDatagram(int(z21::MaxDatagramSize) + 1);
        if (datagram.isValid())
            receive(datagram.data(), datagram.senderAddress(), quint16(datagram.senderPort()));
    }
}

void Z21Server::receive(const QByteArray& datagram, const QHostAddress& from, quint16 port) {
    ++counters_.datagrams;
    if (!allows(from)) {
        ++counters_.notAllowed;
        return;
    }
    bool isNew = false;
    Z21Client& client = clients_.heard(from, port, now(), &isNew);
    if (isNew)
        tell(Z21Event::Kind::Joined, client);
    if (!Z21Clients::admit(client, now(), options_.datagramsPerSecond)) {
        ++counters_.limited;
        if (client.limited == 1)
            tell(Z21Event::Kind::Flooding, client, 0,
                 QStringLiteral("more than %1 datagrams/s").arg(options_.datagramsPerSecond));
        return;
    }
    const auto bytes =
        std::span(reinterpret_cast<const std::uint8_t*>(datagram.constData()), std::size_t(datagram.size()));
    const z21::DatagramRequests read = z21::readRequests(bytes);
    counters_.badPackets += read.errors.size();
    client.badPackets += read.errors.size();
    const QString name = client.name();
    for (const z21::Request& request : read.requests) {
        Z21Client* still = clients_.find(name); // a logoff takes it out of the book
        if (!still)
            return;
        handle(*still, request);
    }
}

void Z21Server::dropSilent() {
    const auto silent = clients_.dropSilent(now(), options_.silence.count());
    for (const Z21Client& client : silent)
        goAway(client, Z21Event::Kind::TimedOut);
}

void Z21Server::goAway(const Z21Client& client, Z21Event::Kind why) {
    QList<quint32> stopped;
    if (railway_)
        stopped = railway_->throttlePort().stopDrivenBy(client.name());
    QStringList what;
    for (const quint32 loco : stopped)
        what << QStringLiteral("0x%1").arg(loco, 4, 16, QLatin1Char('0'));
    tell(why, client, 0,
         what.isEmpty() ? QString() : QStringLiteral("stopped %1").arg(what.join(QLatin1Char(' '))));
}

void Z21Server::send(const Z21Client& client, const z21::Reply& reply) {
    const std::vector<std::uint8_t> bytes = z21::encodeReply(reply);
    socket_->writeDatagram(reinterpret_cast<const char*>(bytes.data()), qint64(bytes.size()), client.address,
                           client.port);
}

void Z21Server::broadcast(std::uint32_t flags, const z21::Reply& reply) {
    for (const auto& [name, client] : clients_.all())
        if (client.flags & flags)
            send(client, reply);
}

void Z21Server::locosChanged(const QList<quint32>& locIds) {
    if (!z21Railway_)
        return;
    for (const quint32 locId : locIds) {
        const std::optional<std::uint16_t> address = z21Railway_->addressOf(locId);
        if (!address)
            continue;
        for (const auto& [name, client] : clients_.all()) {
            const bool wanted =
                (client.flags & z21::broadcast::AllLocos) ||
                ((client.flags & z21::broadcast::DrivingAndSwitching) && client.follows(*address));
            if (wanted)
                sendLocoInfo(client, *address);
        }
    }
}

void Z21Server::sendLocoInfo(const Z21Client& client, std::uint16_t address) {
    if (!z21Railway_)
        return;
    const std::optional<Subscription> followed = client.subscription(address);
    const std::optional<std::uint32_t> loco = z21Railway_->locoAt(address);
    const QString driver = loco ? railway_->throttlePort().owners().driverOf(*loco) : QString();
    const bool busy = !driver.isEmpty() && driver != client.name();
    send(client,
         z21Railway_->locoInfo(address, followed ? followed->mode : z21::SpeedStepMode::Steps128, busy));
}

void Z21Server::turnoutsChanged(const QList<qint64>& keyboardNumbers) {
    if (!z21Railway_)
        return;
    for (const qint64 keyboard : keyboardNumbers)
        if (keyboard >= 1 && keyboard <= 0x10000)
            broadcast(z21::broadcast::DrivingAndSwitching,
                      z21Railway_->turnoutInfo(std::uint16_t(keyboard - 1)));
}

// Track power on or off, and off while the station is not heard or there is no railway ("as the protocol
// allows": the Z21 has no "unknown").
void Z21Server::powerChanged() {
    const std::uint8_t state = z21Railway_ ? z21Railway_->centralState() : z21::central::TrackVoltageOff;
    if (state & z21::central::TrackVoltageOff)
        broadcast(z21::broadcast::DrivingAndSwitching, z21::TrackPowerOff{});
    else if (state & z21::central::EmergencyStop)
        broadcast(z21::broadcast::DrivingAndSwitching, z21::Stopped{});
    else
        broadcast(z21::broadcast::DrivingAndSwitching, z21::TrackPowerOn{});
}

// Last writer wins: the client that drove the locomotive before is sent its info marked busy.
void Z21Server::takenOver(quint32 locId, const QString& from, const QString&) {
    Z21Client* before = clients_.find(from);
    if (!before || !z21Railway_)
        return;
    const std::optional<std::uint16_t> address = z21Railway_->addressOf(locId);
    if (!address)
        return;
    sendLocoInfo(*before, *address);
    tell(Z21Event::Kind::TakenOver, *before, *address, QStringLiteral("taken over"));
}

void Z21Server::tell(Z21Event::Kind kind, const Z21Client& client, std::uint16_t address,
                     const QString& detail) {
    emit event(Z21Event{kind, client.name(), address, detail});
}

} // namespace stellwerk::z21server
