#pragma once

#include <QString>
#include <QStringList>

namespace stellwerk::ui {

// What Stellwerk remembers about layout folders: the ones opened recently (key layout/recent, newest
// first) and the folder the last export went to (key layout/exportFolder).
class LayoutFileSettings final {
public:
    static constexpr int MaxRecent = 8;

    static QStringList recent();
    // Puts `folder` at the front of the recent layouts.
    static void rememberOpened(const QString& folder);
    static void forget(const QString& folder);
    static void clearRecent();
    static QString exportFolder();
    static void rememberExportFolder(const QString& folder);
};

} // namespace stellwerk::ui
