#include "phones/PhoneServers.h"

#include "model/Railway.h"
#include "withrottleserver/MdnsAnnouncement.h"
#include "withrottleserver/WiThrottleServer.h"
#include "z21server/Z21Server.h"

#include <QSettings>
#include <QTimer>

namespace stellwerk::phones {

PhoneServers::PhoneServers(QSettings& settings, QObject* parent)
    : QObject(parent), store_(settings), addresses_(model::Z21Addresses::load(settings)) {}

PhoneServers::~PhoneServers() {
    if (z21_)
        z21_->stopAll();
    if (withrottle_)
        withrottle_->stopAll();
    saveAddresses();
}

QStringList PhoneServers::apply(const PhoneSettings& chosen) {
    settings_ = chosen;
    if (z21_)
        z21_->stopAll();
    if (withrottle_)
        withrottle_->stopAll();
    z21_.reset();
    announcement_.reset();
    withrottle_.reset();
    QStringList problems;
    if (chosen.z21)
        problems << startZ21();
    if (chosen.withrottle)
        problems << startWiThrottle();
    problems.removeAll(QString());
    emit serversChanged();
    emit clientsChanged();
    return problems;
}

QStringList PhoneServers::change(const PhoneSettings& chosen) {
    chosen.save(store_);
    return apply(chosen);
}

QString PhoneServers::startZ21() {
    z21server::Z21ServerOptions options;
    options.address = settings_.z21Listen.address;
    options.port = settings_.z21Listen.port;
    options.allowedClients = settings_.allowedClients;
    z21_ = std::make_unique<z21server::Z21Server>(addresses_, options);
    if (!z21_->listen()) {
        const QString why = QStringLiteral("Z21 %1: %2").arg(settings_.z21Listen.text(), z21_->errorString());
        z21_.reset();
        return why;
    }
    connect(z21_.get(), &z21server::Z21Server::event, this, &PhoneServers::clientsMayHaveChanged);
    z21_->setRailway(railway_);
    return {};
}

QString PhoneServers::startWiThrottle() {
    withrottleserver::WiThrottleServerOptions options;
    options.address = settings_.withrottleListen.address;
    options.port = settings_.withrottleListen.port;
    options.allowedClients = settings_.allowedClients;
    withrottle_ = std::make_unique<withrottleserver::WiThrottleServer>(addresses_, options);
    if (!withrottle_->listen()) {
        const QString why = QStringLiteral("WiThrottle %1: %2")
                                .arg(settings_.withrottleListen.text(), withrottle_->errorString());
        withrottle_.reset();
        return why;
    }
    connect(withrottle_.get(), &withrottleserver::WiThrottleServer::event, this,
            &PhoneServers::clientsMayHaveChanged);
    withrottle_->setRailway(railway_);
    announcement_ = std::make_unique<withrottleserver::MdnsAnnouncement>();
    announcement_->announce(QStringLiteral("Stellwerk"), withrottle_->port());
    return {};
}

QString PhoneServers::announcement() const {
    return announcement_ ? announcement_->why() : QString();
}

void PhoneServers::setRailway(model::Railway* railway) {
    railway_ = railway;
    if (z21_)
        z21_->setRailway(railway);
    if (withrottle_)
        withrottle_->setRailway(railway);
    saveAddresses(); // the servers gave the railway's new locomotives their addresses
    emit clientsChanged();
}

QStringList PhoneServers::clients() const {
    QStringList names;
    if (z21_)
        for (const auto& [key, client] : z21_->clients().all())
            names << client.name();
    if (withrottle_)
        for (const withrottleserver::WiThrottleClient& client : withrottle_->clients())
            if (!client.gone)
                names << client.name();
    return names;
}

// A server tells of a client going before it forgets it: the count is taken once it has.
void PhoneServers::clientsMayHaveChanged() {
    QTimer::singleShot(0, this, &PhoneServers::clientsChanged);
}

void PhoneServers::saveAddresses() {
    addresses_.save(store_);
}

} // namespace stellwerk::phones
