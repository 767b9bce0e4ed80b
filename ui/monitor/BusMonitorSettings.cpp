#include "monitor/BusMonitorSettings.h"

#include "common/StellwerkSettings.h"
#include "monitor/BusMonitorModel.h"

#include <algorithm>

namespace stellwerk::ui {

namespace {

const QString historyKey = QStringLiteral("busMonitor/history");

} // namespace

int BusMonitorSettings::loadHistory() {
    const QSettings settings = stellwerkSettings();
    bool ok = false;
    const int frames = settings.value(historyKey).toInt(&ok);
    return ok ? std::clamp(frames, MinimumHistory, MaximumHistory) : BusMonitorModel::DefaultHistory;
}

void BusMonitorSettings::saveHistory(int frames) {
    QSettings settings = stellwerkSettings();
    settings.setValue(historyKey, std::clamp(frames, MinimumHistory, MaximumHistory));
}

} // namespace stellwerk::ui
