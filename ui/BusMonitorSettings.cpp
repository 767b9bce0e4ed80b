#include "BusMonitorSettings.h"

#include "BusMonitorModel.h"

#include <QSettings>
#include <algorithm>

namespace stellwerk::ui {

namespace {

const QString organisation = QStringLiteral("Stellwerk");
const QString application = QStringLiteral("Stellwerk");
const QString historyKey = QStringLiteral("busMonitor/history");

} // namespace

int BusMonitorSettings::loadHistory() {
    const QSettings settings(organisation, application);
    bool ok = false;
    const int frames = settings.value(historyKey).toInt(&ok);
    return ok ? std::clamp(frames, MinimumHistory, MaximumHistory) : BusMonitorModel::DefaultHistory;
}

void BusMonitorSettings::saveHistory(int frames) {
    QSettings settings(organisation, application);
    settings.setValue(historyKey, std::clamp(frames, MinimumHistory, MaximumHistory));
}

} // namespace stellwerk::ui
