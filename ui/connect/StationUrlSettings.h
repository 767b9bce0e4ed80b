#pragma once

#include <QString>
#include <QStringList>

namespace stellwerk::ui {

// The address of the station Stellwerk connects to at start (key station/url), remembered between runs in
// Stellwerk's settings; empty (or never set) means the embedded simulated station. Also the stations
// connected to recently (key station/recent), newest first, for the Connect dialog. And the further buses
// held open beside the station (key station/furtherBuses), such as a USB-CAN adapter wired to modules.
class StationUrlSettings final {
public:
    static constexpr int MaxRecent = 8;

    static QString load();
    // Stores `url` as the station to use and puts it at the front of the recent ones.
    static void save(const QString& url);
    // Newest first, without duplicates; the simulated station is the empty string.
    static QStringList recent();
    static QStringList furtherBuses();
    static void saveFurtherBuses(const QStringList& addresses);
};

} // namespace stellwerk::ui
