#include "aftertrouble/AftermathSettings.h"

#include "common/StellwerkSettings.h"

namespace stellwerk::ui {
namespace {

const QString aftermathKey = QStringLiteral("station/afterFailedCommand");
const QString stopName = QStringLiteral("stop");

} // namespace

model::Aftermath AftermathSettings::load() {
    return stellwerkSettings().value(aftermathKey).toString() == stopName
               ? model::Aftermath::StopLocomotives
               : model::Aftermath::RestoreConfirmed;
}

void AftermathSettings::save(model::Aftermath aftermath) {
    QSettings settings = stellwerkSettings();
    settings.setValue(aftermathKey,
                      aftermath == model::Aftermath::StopLocomotives ? stopName : QStringLiteral("restore"));
}

} // namespace stellwerk::ui
