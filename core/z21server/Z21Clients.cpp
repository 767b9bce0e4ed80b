#include "z21server/Z21Clients.h"

#include <algorithm>

namespace stellwerk::z21server {
namespace {

QString nameOf(const QHostAddress& address, quint16 port) {
    QHostAddress plain = address;
    bool isV4 = false;
    const quint32 v4 = address.toIPv4Address(&isV4);
    if (isV4)
        plain = QHostAddress(v4);
    return QStringLiteral("z21 %1:%2").arg(plain.toString()).arg(port);
}

} // namespace

QString Z21Client::name() const {
    return nameOf(address, port);
}

void Z21Client::subscribe(std::uint16_t locoAddress, z21::SpeedStepMode mode) {
    std::erase_if(subscriptions, [&](const Subscription& s) { return s.address == locoAddress; });
    subscriptions.push_back({locoAddress, mode});
    while (subscriptions.size() > MaxSubscriptions)
        subscriptions.pop_front();
}

std::optional<Subscription> Z21Client::subscription(std::uint16_t locoAddress) const {
    for (const Subscription& s : subscriptions)
        if (s.address == locoAddress)
            return s;
    return std::nullopt;
}

bool Z21Client::follows(std::uint16_t locoAddress) const {
    return subscription(locoAddress).has_value();
}

Z21Client& Z21Clients::heard(const QHostAddress& address, quint16 port, qint64 nowMs, bool* isNew) {
    const QString name = nameOf(address, port);
    auto it = clients_.find(name);
    if (isNew)
        *isNew = it == clients_.end();
    if (it == clients_.end()) {
        Z21Client client;
        client.address = address;
        client.port = port;
        client.windowStartMs = nowMs;
        it = clients_.emplace(name, std::move(client)).first;
    }
    it->second.lastHeardMs = nowMs;
    return it->second;
}

Z21Client* Z21Clients::find(const QString& name) {
    const auto it = clients_.find(name);
    return it == clients_.end() ? nullptr : &it->second;
}

std::optional<Z21Client> Z21Clients::remove(const QString& name) {
    const auto it = clients_.find(name);
    if (it == clients_.end())
        return std::nullopt;
    Z21Client client = std::move(it->second);
    clients_.erase(it);
    return client;
}

std::vector<Z21Client> Z21Clients::dropSilent(qint64 nowMs, qint64 silenceMs) {
    std::vector<Z21Client> dropped;
    for (auto it = clients_.begin(); it != clients_.end();) {
        if (nowMs - it->second.lastHeardMs >= silenceMs) {
            dropped.push_back(std::move(it->second));
            it = clients_.erase(it);
        } else {
            ++it;
        }
    }
    return dropped;
}

bool Z21Clients::admit(Z21Client& client, qint64 nowMs, int perSecond) {
    if (nowMs - client.windowStartMs >= 1000) {
        client.windowStartMs = nowMs;
        client.datagramsInWindow = 0;
    }
    if (client.datagramsInWindow >= perSecond) {
        ++client.limited;
        return false;
    }
    ++client.datagramsInWindow;
    return true;
}

namespace {

template <class... Ts>
struct Named : Ts... {
    using Ts::operator()...;
};

QString withAddress(const char* name, std::uint16_t address) {
    return QStringLiteral("%1 %2").arg(QLatin1String(name)).arg(address);
}

} // namespace

QString describeRequest(const z21::RequestBody& body) {
    return std::visit(
        Named{
            [](const z21::GetLocoInfo& r) { return withAddress("LAN_X_GET_LOCO_INFO", r.address); },
            [](const z21::SetLocoDrive& r) { return withAddress("LAN_X_SET_LOCO_DRIVE", r.address); },
            [](const z21::SetLocoFunction& r) {
                return withAddress("LAN_X_SET_LOCO_FUNCTION", r.address) +
                       QStringLiteral(" F%1").arg(r.function);
            },
            [](const z21::SetLocoEmergencyStop& r) {
                return withAddress("LAN_X_SET_LOCO_E_STOP", r.address);
            },
            [](const z21::GetTurnoutInfo& r) { return withAddress("LAN_X_GET_TURNOUT_INFO", r.address); },
            [](const z21::SetTurnout& r) { return withAddress("LAN_X_SET_TURNOUT", r.address); },
            [](const z21::SetTrackPowerOn&) { return QStringLiteral("LAN_X_SET_TRACK_POWER_ON"); },
            [](const z21::SetTrackPowerOff&) { return QStringLiteral("LAN_X_SET_TRACK_POWER_OFF"); },
            [](const z21::SetStop&) { return QStringLiteral("LAN_X_SET_STOP"); },
            [](const z21::SetBroadcastFlags&) { return QStringLiteral("LAN_SET_BROADCASTFLAGS"); },
            [](const z21::GetSystemState&) { return QStringLiteral("LAN_SYSTEMSTATE_GETDATA"); },
            [](const z21::GetSerialNumber&) { return QStringLiteral("LAN_GET_SERIAL_NUMBER"); },
            [](const z21::Logoff&) { return QStringLiteral("LAN_LOGOFF"); },
            [](const z21::UnknownRequest& r) {
                return QStringLiteral("unknown 0x%1").arg(r.header, 2, 16, QLatin1Char('0'));
            },
            [](const auto&) { return QStringLiteral("status request"); },
        },
        body);
}

} // namespace stellwerk::z21server
