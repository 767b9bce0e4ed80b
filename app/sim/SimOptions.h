#pragma once

#include "sim/SimulatedStation.h"
#include "sim/StationServer.h"
#include "sim/TrainPlacement.h"

#include <QString>
#include <QStringList>
#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

namespace stellwerk::simapp {

// Everything stellwerk-sim is told on its command line.
inline constexpr int MaximumHandhelds = 31; // M-CAN logins that may run at once (document 6.2)
inline constexpr int MaximumRoModules = 64; // far more than one bus polls at 10 Hz (docs/guide/ro-modules.md)
inline constexpr int MaximumOrcDevices = 64; // decoders, and encoders, each (bus ids 0x0101.., 0x0201..)

struct SimOptions {
    sim::StationServerSettings server;
    std::uint16_t httpPort = 8080; // 0 = no HTTP server
    QString layoutDirectory;       // empty: the demo layout
    bool gleisbox = false;
    bool trains = true;
    std::chrono::milliseconds tick{100};
    // Where the trains start (--place, repeatable); empty: the demo's placements, or spread over the blocks.
    std::vector<sim::TrainPlacement> placements;
    int handhelds = 0;          // simulated MS1s on the station's bus (--ms1)
    bool handheldMaster = true; // the station is the MS1s' M-CAN master (off: --no-handheld-master)
    int roModules = 0;          // simulated RO relay/IO modules on the station's bus (--ro)
    int roLoseEvery = 0;        // every Nth answer of each RO module lost (--ro-lose-every; 0: none)
    std::chrono::milliseconds roDelay{0}; // RO answers this late (--ro-delay)
    // OpenRailCAN devices on the station's bus (--orc-*): a booster whose port overloads and clears every
    // orcOverloadAfter (0: never), decoders, encoders of which an input changes every orcEncoderToggle (0:
    // never), and a throttle that changes the speed of its loco every orcThrottleEvery.
    bool orcBooster = false;
    std::chrono::milliseconds orcOverloadAfter{0};
    int orcOverloadPort = 1;
    int orcDecoders = 0;
    int orcEncoders = 0;
    std::chrono::milliseconds orcEncoderToggle{2000};
    std::optional<std::uint16_t> orcThrottleLoco; // its loco's Ziel-Id
    std::chrono::milliseconds orcThrottleEvery{3000};

    bool hasOrcDevices() const {
        return orcBooster || orcDecoders > 0 || orcEncoders > 0 || orcThrottleLoco.has_value();
    }
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
