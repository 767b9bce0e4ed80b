#include "StationUrlSettings.h"

#include <QSettings>

namespace stellwerk::ui {

namespace {

const QString organisation = QStringLiteral("Stellwerk");
const QString application = QStringLiteral("Stellwerk");
const QString urlKey = QStringLiteral("station/url");

} // namespace

QString StationUrlSettings::load() {
    const QSettings settings(organisation, application);
    return settings.value(urlKey).toString().trimmed();
}

void StationUrlSettings::save(const QString& url) {
    QSettings settings(organisation, application);
    settings.setValue(urlKey, url.trimmed());
}

} // namespace stellwerk::ui
