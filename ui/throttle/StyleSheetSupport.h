#pragma once

#include <QString>

class QWidget;

namespace stellwerk::ui {

// The throttles mark a control the station did not acknowledge in this colour (readable on light and
// dark palettes).
inline constexpr const char* WarningOutline = "#e08a00";

// Applies style sheet rules that select on a dynamic property again after the property changed.
void repolish(QWidget* widget);
// Sets `sheet` again, so that palette(...) in it follows a changed palette. Safe to call from a
// PaletteChange event (setting a style sheet changes the palette once more).
void restyle(QWidget* widget, const QString& sheet);

} // namespace stellwerk::ui
