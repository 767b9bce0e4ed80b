#pragma once

#include <QColor>
#include <QIcon>

namespace stellwerk::ui {

// The small round lamps of the layout overview (track power, occupied contacts), drawn like the lamps
// on a signal box's panel, so that a state is seen before its text is read.
namespace StatusDot {

inline const QColor Occupied{0xc8, 0x2c, 0x2c};
inline const QColor Free{0xb4, 0xb4, 0xb4};
inline const QColor Running{0x2e, 0x9d, 0x3c};
inline const QColor Stopped{0xc8, 0x2c, 0x2c};
inline const QColor Halted{0xe0, 0xa1, 0x1b};
inline const QColor Unknown{0x80, 0x80, 0x80};

// A filled circle of `colour`, `size` pixels wide, with a darker rim.
QIcon icon(const QColor& colour, int size = 12);

} // namespace StatusDot

} // namespace stellwerk::ui
