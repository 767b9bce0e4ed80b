#include "trackplan/LayoutFileSettings.h"

#include "common/StellwerkSettings.h"

#include <QDir>

namespace stellwerk::ui {

namespace {

const QString recentKey = QStringLiteral("layout/recent");
const QString exportKey = QStringLiteral("layout/exportFolder");

QString normalised(const QString& folder) {
    return QDir::cleanPath(QDir(folder).absolutePath());
}

} // namespace

QStringList LayoutFileSettings::recent() {
    QStringList folders;
    for (const QString& folder : stellwerkSettings().value(recentKey).toStringList())
        if (!folder.isEmpty() && !folders.contains(folder))
            folders.append(folder);
    return folders.mid(0, MaxRecent);
}

void LayoutFileSettings::rememberOpened(const QString& folder) {
    QStringList folders = recent();
    folders.removeAll(normalised(folder));
    folders.prepend(normalised(folder));
    stellwerkSettings().setValue(recentKey, folders.mid(0, MaxRecent));
}

void LayoutFileSettings::forget(const QString& folder) {
    QStringList folders = recent();
    folders.removeAll(normalised(folder));
    stellwerkSettings().setValue(recentKey, folders);
}

void LayoutFileSettings::clearRecent() {
    stellwerkSettings().remove(recentKey);
}

QString LayoutFileSettings::exportFolder() {
    return stellwerkSettings().value(exportKey).toString();
}

void LayoutFileSettings::rememberExportFolder(const QString& folder) {
    stellwerkSettings().setValue(exportKey, normalised(folder));
}

} // namespace stellwerk::ui
