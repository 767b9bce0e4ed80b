#pragma once

#include <QByteArray>

namespace stellwerk::ui {

// Where the main window was and how its panels were arranged, as QMainWindow saves them.
struct WindowLayout {
    QByteArray geometry;
    QByteArray state;
};

// The main window's arrangement remembered between runs (keys window/geometry and window/state).
class WindowLayoutSettings final {
public:
    static WindowLayout load();
    static void save(const WindowLayout& layout);
};

} // namespace stellwerk::ui
