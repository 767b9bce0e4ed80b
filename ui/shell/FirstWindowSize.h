#pragma once

#include <QRect>
#include <QSize>

namespace stellwerk::ui {

// Where the main window opens when no size is remembered. A window as large as the screen's free area
// would put its title bar on top of that and push the status bar (station lamp, track power) below the
// screen; so a laptop's screen gets a maximized window, which the window manager fits with its frame, and
// a large screen most of its free area, centred, with room left for any frame.
class FirstWindowSize final {
public:
    // Free areas smaller than this in either direction open maximized.
    static constexpr QSize LargeScreen{1600, 900};

    static bool opensMaximized(const QRect& available);
    // The window's own geometry (without the frame); on a small screen the one it returns to from
    // maximized.
    static QRect geometry(const QRect& available);
};

} // namespace stellwerk::ui
