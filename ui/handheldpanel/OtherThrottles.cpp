#include "handheldpanel/OtherThrottles.h"

#include "model/Railway.h"
#include "model/ThrottlePort.h"
#include "withrottleserver/WiThrottleServer.h"
#include "z21server/Z21Server.h"

namespace stellwerk::ui {

OtherThrottles::OtherThrottles(QObject* parent) : QObject(parent) {}

void OtherThrottles::setServers(z21server::Z21Server* z21, withrottleserver::WiThrottleServer* withrottle) {
    if (m_z21)
        QObject::disconnect(m_z21, nullptr, this, nullptr);
    if (m_withrottle)
        QObject::disconnect(m_withrottle, nullptr, this, nullptr);
    m_z21 = z21;
    m_withrottle = withrottle;
    if (m_z21) {
        connect(m_z21, &z21server::Z21Server::event, this, &OtherThrottles::changed);
        connect(m_z21, &QObject::destroyed, this, &OtherThrottles::changed, Qt::QueuedConnection);
    }
    if (m_withrottle) {
        connect(m_withrottle, &withrottleserver::WiThrottleServer::event, this, &OtherThrottles::changed);
        connect(m_withrottle, &QObject::destroyed, this, &OtherThrottles::changed, Qt::QueuedConnection);
    }
    emit changed();
}

void OtherThrottles::setRailway(model::Railway* railway) {
    if (m_railway)
        QObject::disconnect(&m_railway->throttlePort().owners(), nullptr, this, nullptr);
    m_railway = railway;
    if (m_railway)
        connect(&m_railway->throttlePort().owners(), &model::LocoOwners::driverChanged, this,
                &OtherThrottles::changed);
    emit changed();
}

std::vector<ThrottleRow> OtherThrottles::rows() const {
    std::vector<ThrottleRow> rows;
    addOpenRailCan(rows);
    addZ21(rows);
    addWiThrottle(rows);
    return rows;
}

void OtherThrottles::addZ21(std::vector<ThrottleRow>& rows) const {
    if (!m_z21)
        return;
    for (const auto& [name, client] : m_z21->clients().all()) {
        ThrottleRow row;
        row.kind = ThrottleRow::Kind::Z21;
        row.key = name;
        row.address = QStringLiteral("%1:%2").arg(client.address.toString()).arg(client.port);
        row.name = QStringLiteral(
            "\u2014"); // the Z21 protocol carries no device name: a dash, not the address again
        row.locomotives = locomotives(name);
        row.lastAt = client.lastRequestAt;
        row.lastText = client.lastRequest;
        row.canDisconnect = true;
        rows.push_back(std::move(row));
    }
}

void OtherThrottles::addWiThrottle(std::vector<ThrottleRow>& rows) const {
    if (!m_withrottle)
        return;
    for (const withrottleserver::WiThrottleClient& client : m_withrottle->clients()) {
        if (client.gone)
            continue;
        ThrottleRow row;
        row.kind = ThrottleRow::Kind::WiThrottle;
        row.key = client.name();
        row.address = client.peer;
        row.name = QString::fromStdString(client.deviceName);
        row.locomotives = locomotives(row.key);
        row.lastAt = client.lastLineAt;
        row.lastText = client.lastLine;
        row.canDisconnect = true;
        rows.push_back(std::move(row));
    }
}

// The OpenRailCAN throttles on the station's buses drive under one name: one row while they drive.
void OtherThrottles::addOpenRailCan(std::vector<ThrottleRow>& rows) const {
    const QString name = model::ThrottlePort::orcThrottles();
    const QStringList driven = locomotives(name);
    if (driven.isEmpty())
        return;
    ThrottleRow row;
    row.kind = ThrottleRow::Kind::OpenRailCan;
    row.key = name;
    row.address = tr("CAN bus");
    row.locomotives = driven;
    rows.push_back(std::move(row));
}

QStringList OtherThrottles::locomotives(const QString& throttle) const {
    QStringList names;
    if (!m_railway)
        return names;
    for (const quint32 locId : m_railway->throttlePort().owners().drivenBy(throttle)) {
        const model::Locomotive* loco = m_railway->locomotive(locId);
        names << (loco ? loco->displayName() : QStringLiteral("0x%1").arg(locId, 4, 16, QLatin1Char('0')));
    }
    names.sort();
    return names;
}

bool OtherThrottles::letGo(const QString& key) {
    const bool done = (m_z21 && m_z21->dropClient(key)) || (m_withrottle && m_withrottle->dropClient(key));
    if (done)
        emit changed();
    return done;
}

} // namespace stellwerk::ui
