#include "mcanhandhelds/HandheldBook.h"

#include <QSettings>
#include <QStringList>

namespace stellwerk::mcanhandhelds {
namespace {

QString groupOf(std::uint32_t uid) {
    return QStringLiteral("mcanhandhelds/%1").arg(uid, 8, 16, QLatin1Char('0'));
}

} // namespace

std::optional<SavedHandheld> MemoryHandheldBook::load(std::uint32_t uid) const {
    const auto found = saved_.find(uid);
    return found == saved_.end() ? std::nullopt : std::optional(found->second);
}

void MemoryHandheldBook::save(std::uint32_t uid, const SavedHandheld& handheld) {
    saved_[uid] = handheld;
}

std::optional<SavedHandheld> SettingsHandheldBook::load(std::uint32_t uid) const {
    QSettings settings(organization_, application_);
    settings.beginGroup(groupOf(uid));
    if (!settings.contains(QStringLiteral("stack")))
        return std::nullopt;
    SavedHandheld saved{settings.value(QStringLiteral("name")).toString(), {}};
    for (const QString& id : settings.value(QStringLiteral("stack")).toStringList()) {
        bool ok = false;
        const std::uint32_t locId = id.toUInt(&ok, 16);
        if (ok)
            saved.stack.push_back(locId);
    }
    return saved;
}

void SettingsHandheldBook::save(std::uint32_t uid, const SavedHandheld& handheld) {
    QSettings settings(organization_, application_);
    settings.beginGroup(groupOf(uid));
    settings.setValue(QStringLiteral("name"), handheld.name);
    QStringList stack;
    for (const std::uint32_t locId : handheld.stack)
        stack << QString::number(locId, 16);
    settings.setValue(QStringLiteral("stack"), stack);
}

} // namespace stellwerk::mcanhandhelds
