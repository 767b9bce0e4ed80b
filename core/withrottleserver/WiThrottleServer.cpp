#include "withrottleserver/WiThrottleServer.h"

#include "model/Railway.h"

#include <QTcpServer>
#include <QTcpSocket>
#include <QTimer>
#include <algorithm>

namespace stellwerk::withrottleserver {

WiThrottleServer::WiThrottleServer(model::Z21Addresses& addresses, WiThrottleServerOptions options,
                                   QObject* parent)
    : QObject(parent), addresses_(addresses), options_(std::move(options)), listener_(new QTcpServer(this)),
      heartbeatTimer_(new QTimer(this)), follower_(railwayChanges()) {
    clock_.start();
    connect(listener_, &QTcpServer::newConnection, this, &WiThrottleServer::accept);
    const auto tick =
        std::clamp(options_.heartbeat / 4, std::chrono::milliseconds(20), std::chrono::milliseconds(1000));
    heartbeatTimer_->setInterval(tick);
    connect(heartbeatTimer_, &QTimer::timeout, this, &WiThrottleServer::dropSilent);
}

WiThrottleServer::~WiThrottleServer() {
    for (WiThrottleClient& client : clients_)
        if (client.socket)
            client.socket->disconnect(this);
}

bool WiThrottleServer::listen() {
    if (!listener_->listen(options_.address, options_.port))
        return false;
    heartbeatTimer_->start();
    return true;
}

QString WiThrottleServer::errorString() const {
    return listener_->errorString();
}

quint16 WiThrottleServer::port() const {
    return listener_->serverPort();
}

std::size_t WiThrottleServer::clientCount() const {
    return std::size_t(
        std::count_if(clients_.begin(), clients_.end(), [](const WiThrottleClient& c) { return !c.gone; }));
}

void WiThrottleServer::setRailway(model::Railway* railway) {
    if (railway_ == railway)
        return;
    railway_ = railway;
    wiRailway_ = railway ? std::make_unique<WiThrottleRailway>(*railway, addresses_) : nullptr;
    if (wiRailway_)
        wiRailway_->coverLocomotives();
    follower_.follow(railway);
    powerChanged();
}

model::RailwayFollower::Changes WiThrottleServer::railwayChanges() {
    model::RailwayFollower::Changes changes;
    changes.loaded = [this] {
        if (wiRailway_)
            wiRailway_->coverLocomotives();
    };
    changes.locomotives = [this](const QList<quint32>& locIds) { locosChanged(locIds); };
    changes.accessories = [this](const QList<qint64>& numbers) { turnoutsChanged(numbers); };
    changes.routeFinished = [this] { routesChanged(); };
    changes.power = [this] { powerChanged(); };
    changes.takenOver = [this](quint32 locId, const QString& from, const QString& to) {
        takenOver(locId, from, to);
    };
    changes.gone = [this] {
        wiRailway_.reset();
        powerChanged();
    };
    return changes;
}

void WiThrottleServer::stopAll() {
    for (WiThrottleClient& client : clients_)
        if (!client.gone)
            goAway(client, WiThrottleEvent::Kind::Left);
    clients_.clear();
}

bool WiThrottleServer::allows(const QHostAddress& peer) const {
    return options_.allowedClients.isEmpty() ||
           std::any_of(options_.allowedClients.cbegin(), options_.allowedClients.cend(),
                       [&peer](const QHostAddress& allowed) { return allowed.isEqual(peer); });
}

bool WiThrottleServer::dropClient(const QString& client) {
    WiThrottleClient* found = find(client);
    if (!found)
        return false;
    goAway(*found, WiThrottleEvent::Kind::Dropped);
    return true;
}

void WiThrottleServer::accept() {
    while (QTcpSocket* socket = listener_->nextPendingConnection()) {
        socket->setParent(this);
        if (!allows(socket->peerAddress())) {
            ++counters_.notAllowed;
            socket->abort();
            socket->deleteLater();
            continue;
        }
        WiThrottleClient& client = clients_.emplace_back();
        client.socket = socket;
        client.peer = QStringLiteral("%1:%2").arg(socket->peerAddress().toString()).arg(socket->peerPort());
        client.splitter = withrottle::LineSplitter(options_.maxLineLength);
        client.lastHeardMs = now();
        ++counters_.connections;
        connect(socket, &QTcpSocket::readyRead, this, [this, socket] {
            if (WiThrottleClient* found = find(socket))
                read(*found);
        });
        connect(socket, &QTcpSocket::disconnected, this, [this, socket] {
            if (WiThrottleClient* found = find(socket))
                goAway(*found, WiThrottleEvent::Kind::Left);
        });
        tell(WiThrottleEvent::Kind::Joined, client);
        greet(client);
    }
}

WiThrottleClient* WiThrottleServer::find(const QTcpSocket* socket) {
    const auto it = std::find_if(clients_.begin(), clients_.end(), [&](const WiThrottleClient& client) {
        return !client.gone && client.socket == socket;
    });
    return it == clients_.end() ? nullptr : &*it;
}

WiThrottleClient* WiThrottleServer::find(const QString& name) {
    const auto it = std::find_if(clients_.begin(), clients_.end(), [&](const WiThrottleClient& client) {
        return !client.gone && client.name() == name;
    });
    return it == clients_.end() ? nullptr : &*it;
}

void WiThrottleServer::read(WiThrottleClient& client) {
    const QByteArray bytes = client.socket->readAll();
    client.lastHeardMs = now();
    const std::size_t overlongBefore = client.splitter.overlongLines();
    const std::vector<std::string> lines =
        client.splitter.feed(std::string_view(bytes.constData(), std::size_t(bytes.size())));
    counters_.overlongLines += client.splitter.overlongLines() - overlongBefore;
    for (const std::string& line : lines) {
        if (client.gone)
            return;
        if (!client.admit(now(), options_.linesPerSecond)) {
            ++counters_.limited;
            if (client.limited == 1)
                tell(WiThrottleEvent::Kind::Flooding, client,
                     QStringLiteral("more than %1 lines/s").arg(options_.linesPerSecond));
            continue;
        }
        ++counters_.lines;
        ++client.lines;
        client.lastLineAt = QDateTime::currentDateTime();
        client.lastLine = QString::fromStdString(line).left(60);
        handle(client, withrottle::parseClientLine(line));
    }
}

// What JMRI's server sends a new connection: version, server, roster, power, turnouts, routes, heartbeat.
void WiThrottleServer::greet(WiThrottleClient& client) {
    send(client, withrottle::ProtocolVersion{});
    send(client, withrottle::ServerType{options_.serverName});
    send(client, withrottle::ServerDescription{options_.serverName + " WiThrottle server"});
    send(client, wiRailway_ ? wiRailway_->roster() : withrottle::RosterList{});
    send(client, withrottle::PowerStatus{wiRailway_ ? wiRailway_->power() : withrottle::PowerState::Unknown});
    send(client, withrottle::TurnoutTitles{});
    send(client, wiRailway_ ? wiRailway_->turnouts() : withrottle::TurnoutList{});
    send(client, withrottle::RouteTitles{});
    send(client, wiRailway_ ? wiRailway_->routes() : withrottle::RouteList{});
    send(client, withrottle::HeartbeatInterval{heartbeatSeconds()});
}

int WiThrottleServer::heartbeatSeconds() const {
    const auto seconds = std::chrono::ceil<std::chrono::seconds>(options_.heartbeat).count();
    return int(std::max<std::int64_t>(1, seconds));
}

void WiThrottleServer::dropSilent() {
    const qint64 limit = (options_.heartbeat + options_.grace).count();
    for (WiThrottleClient& client : clients_)
        if (!client.gone && client.heartbeatWatched && now() - client.lastHeardMs > limit)
            goAway(client, WiThrottleEvent::Kind::TimedOut);
}

// Stops what the client drove, closes its connection and takes it out of the book once the event loop is
// back (a caller may still hold the client).
void WiThrottleServer::goAway(WiThrottleClient& client, WiThrottleEvent::Kind why) {
    if (client.gone)
        return;
    client.gone = true;
    QList<quint32> stopped;
    if (railway_)
        stopped = railway_->throttlePort().stopDrivenBy(client.name());
    QStringList what;
    for (const quint32 loco : stopped)
        what << QStringLiteral("0x%1").arg(loco, 4, 16, QLatin1Char('0'));
    tell(why, client,
         what.isEmpty() ? QString() : QStringLiteral("stopped %1").arg(what.join(QLatin1Char(' '))));
    if (client.socket) {
        client.socket->disconnect(this);
        client.socket->abort();
        client.socket->deleteLater();
    }
    QTimer::singleShot(0, this,
                       [this] { std::erase_if(clients_, [](const WiThrottleClient& c) { return c.gone; }); });
}

void WiThrottleServer::send(WiThrottleClient& client, const withrottle::ServerLine& line) {
    if (client.gone || !client.socket)
        return;
    const std::string text = withrottle::formatServerLine(line) + "\n";
    client.socket->write(text.data(), qint64(text.size()));
}

void WiThrottleServer::sendAll(const withrottle::ServerLine& line) {
    for (WiThrottleClient& client : clients_)
        send(client, line);
}

void WiThrottleServer::locosChanged(const QList<quint32>& locIds) {
    for (const quint32 locId : locIds)
        for (WiThrottleClient& client : clients_)
            for (auto& [throttle, loco] : client.holdersOf(locId))
                tellLoco(client, throttle, *loco);
}

// Speed, direction and the functions as the railway shows them, where they differ from what the client was
// last told (everything the first time).
void WiThrottleServer::tellLoco(WiThrottleClient& client, char throttle, ThrottleLoco& loco) {
    const std::optional<model::LocoRun> run =
        railway_ ? railway_->throttlePort().shown(loco.locId) : std::nullopt;
    if (!run)
        return;
    const auto status = [&](withrottle::LocoUpdate update) {
        send(client, withrottle::LocoStatus{throttle, loco.key, update});
    };
    const std::optional<model::LocoRun> told = loco.told;
    for (int function = 0; function <= withrottle::HighestFunction; ++function) {
        const bool on = (run->functions >> function) & 1u;
        if (!told || on != bool((told->functions >> function) & 1u))
            status(withrottle::FunctionState{std::uint8_t(function), on});
    }
    if (!told || told->speed != run->speed)
        status(withrottle::SpeedState{WiThrottleRailway::throttleSpeed(run->speed)});
    if (!told || told->forward != run->forward)
        status(withrottle::DirectionState{run->forward});
    if (!told)
        status(withrottle::SpeedStepState{1});
    loco.told = run;
}

void WiThrottleServer::turnoutsChanged(const QList<qint64>& keyboardNumbers) {
    if (!wiRailway_)
        return;
    for (const qint64 keyboard : keyboardNumbers) {
        const model::Accessory* accessory = railway_->accessory(keyboard);
        if (accessory && accessory->positionCount() == 2)
            sendAll(withrottle::TurnoutChanged{WiThrottleRailway::turnoutName(keyboard),
                                               wiRailway_->turnoutState(keyboard)});
    }
    routesChanged();
}

void WiThrottleServer::routesChanged() {
    if (!wiRailway_)
        return;
    for (const withrottle::RouteEntry& route : wiRailway_->routes().routes)
        sendAll(withrottle::RouteChanged{route.systemName,
                                         route.state.value_or(withrottle::RouteState::Unknown)});
}

// On, off, or unknown (PPA2) while the station is not heard or there is no railway.
void WiThrottleServer::powerChanged() {
    sendAll(withrottle::PowerStatus{wiRailway_ ? wiRailway_->power() : withrottle::PowerState::Unknown});
}

// Another throttle drives the loco now (a steal, a Z21 client, a handheld): the client that held it is
// told it lost it, and it leaves its throttles.
void WiThrottleServer::takenOver(quint32 locId, const QString& from, const QString& to) {
    WiThrottleClient* before = find(from);
    if (!before)
        return;
    for (const auto& [throttle, key] : before->forget(locId)) {
        send(*before, withrottle::ThrottleReply{throttle, withrottle::ThrottleReplyKind::Removed, key});
        send(*before, withrottle::ServerMessage{"Loco " + key + " taken over by " + to.toStdString()});
        tell(WiThrottleEvent::Kind::TakenOver, *before,
             QStringLiteral("%1 by %2").arg(QString::fromStdString(key), to));
    }
}

void WiThrottleServer::tell(WiThrottleEvent::Kind kind, const WiThrottleClient& client,
                            const QString& detail) {
    emit event(WiThrottleEvent{kind, client.name(), detail});
}

} // namespace stellwerk::withrottleserver
