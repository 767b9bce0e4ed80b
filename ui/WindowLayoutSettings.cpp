#include "WindowLayoutSettings.h"

#include <QSettings>

namespace stellwerk::ui {

namespace {

const QString organisation = QStringLiteral("Stellwerk");
const QString application = QStringLiteral("Stellwerk");
const QString geometryKey = QStringLiteral("window/geometry");
const QString stateKey = QStringLiteral("window/state");

} // namespace

WindowLayout WindowLayoutSettings::load() {
    const QSettings settings(organisation, application);
    return {settings.value(geometryKey).toByteArray(), settings.value(stateKey).toByteArray()};
}

void WindowLayoutSettings::save(const WindowLayout& layout) {
    QSettings settings(organisation, application);
    settings.setValue(geometryKey, layout.geometry);
    settings.setValue(stateKey, layout.state);
}

} // namespace stellwerk::ui
