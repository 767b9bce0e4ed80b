#pragma once

#include "sim/SimulatedStation.h"
#include "sim/StationServer.h"

#include <QString>
#include <QStringList>
#include <chrono>
#include <cstdint>
#include <optional>

namespace stellwerk::simapp {

// Everything stellwerk-sim is told on its command line.
inline constexpr int MaximumHandhelds = 31; // M-CAN logins that may run at once (document 6.2)

struct SimOptions {
    sim::StationServerSettings server;
    std::uint16_t httpPort = 8080; // 0 = no HTTP server
    QString layoutDirectory;       // empty: the demo layout
    bool gleisbox = false;
    bool trains = true;
    std::chrono::milliseconds tick{100};
    int handhelds = 0;          // simulated MS1s on the station's bus (--ms1)
    bool handheldMaster = true; // the station is the MS1s' M-CAN master (off: --no-handheld-master)
};

// The result of reading the command line: options, or a message for the user (and whether it is an error).
struct ParsedOptions {
    std::optional<SimOptions> options;
    QString message;
    bool error = false;
};

// Reads `arguments` (argv, program name first) with QCommandLineParser.
ParsedOptions parseSimOptions(const QStringList& arguments);

} // namespace stellwerk::simapp
