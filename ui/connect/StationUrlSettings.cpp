#include "connect/StationUrlSettings.h"

#include "common/StellwerkSettings.h"

namespace stellwerk::ui {

namespace {

const QString urlKey = QStringLiteral("station/url");
const QString recentKey = QStringLiteral("station/recent");
const QString furtherBusesKey = QStringLiteral("station/furtherBuses");

} // namespace

QString StationUrlSettings::load() {
    const QSettings settings = stellwerkSettings();
    return settings.value(urlKey).toString().trimmed();
}

void StationUrlSettings::save(const QString& url) {
    const QString chosen = url.trimmed();
    QStringList recent = StationUrlSettings::recent();
    recent.removeAll(chosen);
    recent.prepend(chosen);
    while (recent.size() > MaxRecent)
        recent.removeLast();
    QSettings settings = stellwerkSettings();
    settings.setValue(urlKey, chosen);
    settings.setValue(recentKey, recent);
}

QStringList StationUrlSettings::recent() {
    const QSettings settings = stellwerkSettings();
    QStringList recent;
    for (const QString& url : settings.value(recentKey).toStringList()) {
        if (!recent.contains(url.trimmed()))
            recent.append(url.trimmed());
    }
    return recent;
}

QStringList StationUrlSettings::furtherBuses() {
    const QSettings settings = stellwerkSettings();
    QStringList addresses;
    for (const QString& address : settings.value(furtherBusesKey).toStringList())
        if (!address.trimmed().isEmpty())
            addresses.append(address.trimmed());
    return addresses;
}

void StationUrlSettings::saveFurtherBuses(const QStringList& addresses) {
    QSettings settings = stellwerkSettings();
    settings.setValue(furtherBusesKey, addresses);
}

} // namespace stellwerk::ui
