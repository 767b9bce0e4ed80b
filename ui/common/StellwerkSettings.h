#pragma once

#include <QSettings>

namespace stellwerk::ui {

// Where every choice Stellwerk remembers lives: the settings of organisation and application "Stellwerk".
// The typed settings classes (LanguageSettings, StationUrlSettings, ...) read and write through it.
inline QSettings stellwerkSettings() {
    return QSettings(QStringLiteral("Stellwerk"), QStringLiteral("Stellwerk"));
}

} // namespace stellwerk::ui
