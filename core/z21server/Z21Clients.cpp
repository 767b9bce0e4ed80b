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

} // namespace stellwerk::z21server
