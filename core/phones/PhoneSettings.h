#pragma once

#include "phones/ListenAddress.h"

#include <QHostAddress>
#include <QList>

class QSettings;

namespace stellwerk::phones {

// What the user chose for the phone servers (issue 35): each on or off (both off by default), where it
// listens, and which client addresses may use them (none listed: every one). Kept in the settings' group
// "phones".
struct PhoneSettings {
    static constexpr quint16 Z21Port = 21105;        // the Z21's own
    static constexpr quint16 WiThrottlePort = 12090; // JMRI's

    bool z21 = false;
    ListenAddress z21Listen{QHostAddress::Any, Z21Port};
    bool withrottle = false;
    ListenAddress withrottleListen{QHostAddress::Any, WiThrottlePort};
    QList<QHostAddress> allowedClients;

    bool anyOn() const { return z21 || withrottle; }

    static PhoneSettings load(QSettings& settings);
    void save(QSettings& settings) const;
    // "192.168.1.30, 192.168.1.31" and back; nullopt when a word is no address.
    static std::optional<QList<QHostAddress>> parseClients(const QString& text);
    static QString clientsText(const QList<QHostAddress>& clients);

    friend bool operator==(const PhoneSettings&, const PhoneSettings&) = default;
};

} // namespace stellwerk::phones
