#include "throttle/ThrottleSettings.h"

#include "common/StellwerkSettings.h"

#include <QStringList>

namespace stellwerk::ui {
namespace {

const QString locomotivesKey = QStringLiteral("throttles/locomotives");

} // namespace

QList<std::uint32_t> ThrottleSettings::load() {
    const QSettings settings = stellwerkSettings();
    QList<std::uint32_t> locomotives;
    // Stored as "0x4001" texts: readable in the settings file, and a damaged entry only loses itself.
    for (const QString& text : settings.value(locomotivesKey).toStringList()) {
        bool ok = false;
        const std::uint32_t loco = text.toUInt(&ok, 0);
        locomotives.push_back(ok ? loco : 0);
        if (locomotives.size() == MaximumThrottles)
            break;
    }
    return locomotives;
}

void ThrottleSettings::save(const QList<std::uint32_t>& locomotives) {
    QStringList texts;
    for (const std::uint32_t loco : locomotives)
        texts << QStringLiteral("0x%1").arg(loco, 0, 16);
    QSettings settings = stellwerkSettings();
    settings.setValue(locomotivesKey, texts);
}

} // namespace stellwerk::ui
