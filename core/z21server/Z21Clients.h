#pragma once

#include "z21/LocoSpeed.h"
#include "z21/Requests.h"

#include <QDateTime>
#include <QHostAddress>
#include <QString>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <vector>

namespace stellwerk::z21server {

// A locomotive a client asked about or drove, with the steps it drives it in.
struct Subscription {
    std::uint16_t address = 0;
    z21::SpeedStepMode mode = z21::SpeedStepMode::Steps128;
};

// One Z21 client as the server knows it (address and port, spec 1.1): its broadcast flags, the locomotives
// it follows, when it was last heard, and what it sent that was wrong or too much.
struct Z21Client {
    // The spec's limit of locomotives followed per client (4.1): the oldest is forgotten first.
    static constexpr std::size_t MaxSubscriptions = 16;

    QHostAddress address;
    quint16 port = 0;
    std::uint32_t flags = 0;
    std::deque<Subscription> subscriptions;
    qint64 lastHeardMs = 0;
    QDateTime lastRequestAt;  // wall-clock time of the last request read, for the Throttles panel
    QString lastRequest;      // that request's name in the spec with its address: "LAN_X_SET_LOCO_DRIVE 3"
    qint64 windowStartMs = 0; // the flood limit's one-second window
    int datagramsInWindow = 0;
    std::uint64_t requests = 0;
    std::uint64_t wrongChecksums = 0;
    std::uint64_t badPackets = 0;
    std::uint64_t limited = 0;

    // The throttle name the owner book knows it by: "z21 192.168.1.20:61234".
    QString name() const;
    void subscribe(std::uint16_t locoAddress, z21::SpeedStepMode mode);
    std::optional<Subscription> subscription(std::uint16_t locoAddress) const;
    bool follows(std::uint16_t locoAddress) const;
};

// A request as the specification names it, with the locomotive or turnout address where it has one.
QString describeRequest(const z21::RequestBody& body);

// The clients the server has heard, by address and port: who is new, who fell silent, who floods.
class Z21Clients {
public:
    // The client that sent a datagram now; `isNew` tells whether it was unknown until now.
    Z21Client& heard(const QHostAddress& address, quint16 port, qint64 nowMs, bool* isNew = nullptr);
    Z21Client* find(const QString& name);
    // Takes the client out of the book and returns it.
    std::optional<Z21Client> remove(const QString& name);
    // The clients silent for `silenceMs` or longer, taken out of the book.
    std::vector<Z21Client> dropSilent(qint64 nowMs, qint64 silenceMs);
    // Whether one more datagram of the client is within `perSecond`; false ones are counted and dropped.
    static bool admit(Z21Client& client, qint64 nowMs, int perSecond);

    std::map<QString, Z21Client>& all() { return clients_; }
    const std::map<QString, Z21Client>& all() const { return clients_; }
    std::size_t size() const { return clients_.size(); }

private:
    std::map<QString, Z21Client> clients_;
};

} // namespace stellwerk::z21server
