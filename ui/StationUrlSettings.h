#pragma once

#include <QString>

namespace stellwerk::ui {

// The address of the station Stellwerk connects to at start (key station/url), remembered between runs in
// Stellwerk's settings; empty (or never set) means the embedded simulated station.
class StationUrlSettings final {
public:
    static QString load();
    static void save(const QString& url);
};

} // namespace stellwerk::ui
