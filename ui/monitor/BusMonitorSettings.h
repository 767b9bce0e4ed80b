#pragma once

namespace stellwerk::ui {

// How many frames the bus monitor keeps (key busMonitor/history), remembered between runs.
class BusMonitorSettings final {
public:
    static constexpr int MinimumHistory = 1000;
    static constexpr int MaximumHistory = 1000000;

    // The stored value within the bounds above, or BusMonitorModel's default when none was stored.
    static int loadHistory();
    static void saveHistory(int frames);
};

} // namespace stellwerk::ui
