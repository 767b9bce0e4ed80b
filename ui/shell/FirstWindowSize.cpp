#include "shell/FirstWindowSize.h"

namespace stellwerk::ui {

bool FirstWindowSize::opensMaximized(const QRect& available) {
    return available.width() < LargeScreen.width() || available.height() < LargeScreen.height();
}

// Nine tenths of the free area leave at least 76 px above and below for a title bar on a large screen.
QRect FirstWindowSize::geometry(const QRect& available) {
    QRect window(QPoint(), available.size() * 9 / 10);
    window.moveCenter(available.center());
    return window;
}

} // namespace stellwerk::ui
