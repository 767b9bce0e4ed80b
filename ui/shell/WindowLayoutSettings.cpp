#include "shell/WindowLayoutSettings.h"

#include "common/StellwerkSettings.h"

namespace stellwerk::ui {

namespace {

const QString geometryKey = QStringLiteral("window/geometry");
const QString stateKey = QStringLiteral("window/state");

} // namespace

WindowLayout WindowLayoutSettings::load() {
    const QSettings settings = stellwerkSettings();
    return {settings.value(geometryKey).toByteArray(), settings.value(stateKey).toByteArray()};
}

void WindowLayoutSettings::save(const WindowLayout& layout) {
    QSettings settings = stellwerkSettings();
    settings.setValue(geometryKey, layout.geometry);
    settings.setValue(stateKey, layout.state);
}

} // namespace stellwerk::ui
