#include "phones/PhoneSettings.h"

#include <QRegularExpression>
#include <QSettings>

namespace stellwerk::phones {
namespace {

ListenAddress listenOf(const QSettings& settings, const QString& key, quint16 defaultPort) {
    return ListenAddress::parse(settings.value(key).toString(), defaultPort)
        .value_or(ListenAddress{QHostAddress::Any, defaultPort});
}

} // namespace

PhoneSettings PhoneSettings::load(QSettings& settings) {
    PhoneSettings loaded;
    settings.beginGroup(QStringLiteral("phones"));
    loaded.z21 = settings.value(QStringLiteral("z21"), false).toBool();
    loaded.z21Listen = listenOf(settings, QStringLiteral("z21Listen"), Z21Port);
    loaded.withrottle = settings.value(QStringLiteral("withrottle"), false).toBool();
    loaded.withrottleListen = listenOf(settings, QStringLiteral("withrottleListen"), WiThrottlePort);
    loaded.allowedClients =
        parseClients(settings.value(QStringLiteral("allowedClients")).toStringList().join(QLatin1Char(' ')))
            .value_or(QList<QHostAddress>());
    settings.endGroup();
    return loaded;
}

void PhoneSettings::save(QSettings& settings) const {
    settings.beginGroup(QStringLiteral("phones"));
    settings.setValue(QStringLiteral("z21"), z21);
    settings.setValue(QStringLiteral("z21Listen"), z21Listen.text());
    settings.setValue(QStringLiteral("withrottle"), withrottle);
    settings.setValue(QStringLiteral("withrottleListen"), withrottleListen.text());
    QStringList clients;
    for (const QHostAddress& client : allowedClients)
        clients << client.toString();
    settings.setValue(QStringLiteral("allowedClients"), clients);
    settings.endGroup();
}

std::optional<QList<QHostAddress>> PhoneSettings::parseClients(const QString& text) {
    static const QRegularExpression separators(QStringLiteral("[,;\\s]+"));
    QList<QHostAddress> clients;
    for (const QString& word : text.split(separators, Qt::SkipEmptyParts)) {
        QHostAddress address;
        if (!address.setAddress(word))
            return std::nullopt;
        clients << address;
    }
    return clients;
}

QString PhoneSettings::clientsText(const QList<QHostAddress>& clients) {
    QStringList words;
    for (const QHostAddress& client : clients)
        words << client.toString();
    return words.join(QStringLiteral(", "));
}

} // namespace stellwerk::phones
