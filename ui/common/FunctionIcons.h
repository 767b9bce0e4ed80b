#pragma once

#include <QCoreApplication>
#include <QIcon>
#include <QString>
#include <cstdint>

class QColor;

namespace stellwerk::ui {

// What a function key does, as far as its CS2 icon number tells. `Numbered` is every icon we do not
// draw: the key shows its number instead.
enum class FunctionKind : std::uint8_t {
    Numbered,
    Light,
    InteriorLight,
    CabLight,
    Sound,
    Horn,
    Whistle,
    Bell,
    Smoke,
    Coupler,
    Shunting,
    BrakeSound,
    Pantograph,
    Inertia,
    Announcement,
};

// The one table from CS2 function icon numbers (`..typ`) to our own drawings (resources/function-icons,
// embedded under :/function-icons/), so that throttles show light, horn, coupler... as the station does.
class FunctionIcons final {
    Q_DECLARE_TR_FUNCTIONS(FunctionIcons)

public:
    // The kind of a CS2 icon number; bit 7 (the momentary marker) is ignored.
    static FunctionKind kindOf(int cs2Icon);
    // ":/function-icons/horn.svg"; empty for Numbered.
    static QString resourcePath(FunctionKind kind);
    // The kind in the user's language ("Horn"); "Function" for Numbered.
    static QString name(FunctionKind kind);
    // The drawing in `color` (so that it reads on light and dark palettes), `size` pixels square; a null
    // icon for Numbered.
    static QIcon icon(FunctionKind kind, const QColor& color, int size);
};

} // namespace stellwerk::ui
