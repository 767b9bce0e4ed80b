#pragma once

#include "connection/StationConnection.h"
#include "sim/EmbeddedStation.h"

namespace stellwerk::support {

// Connection settings whose local station is the embedded simulated CS2, handed over the way the GUI
// program does it (the connection layer itself never links the simulator).
inline connection::ConnectionSettings withEmbeddedStation(connection::ConnectionSettings settings = {}) {
    settings.localStation = sim::EmbeddedStation::factory();
    return settings;
}

} // namespace stellwerk::support
