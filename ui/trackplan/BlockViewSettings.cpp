#include "trackplan/BlockViewSettings.h"

#include "common/StellwerkSettings.h"

namespace stellwerk::ui {
namespace {

const QString shownKey = QStringLiteral("trackPlan/blocks");

} // namespace

bool BlockViewSettings::shown() {
    return stellwerkSettings().value(shownKey, false).toBool();
}

void BlockViewSettings::setShown(bool shown) {
    stellwerkSettings().setValue(shownKey, shown);
}

} // namespace stellwerk::ui
