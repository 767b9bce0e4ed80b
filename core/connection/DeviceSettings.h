#pragma once

#include "orccentral/OrcSession.h"
#include "ro/RoProfile.h"
#include "romodule/RoModuleSession.h"

#include <QString>
#include <chrono>
#include <vector>

class QSettings;

namespace stellwerk::connection {

// The OpenRailCAN central: whether Stellwerk is it, and on which bus (0: the station's, 1..: the further
// buses in the order given to connectTo()).
struct OrcCentralSettings {
    bool on = false;
    int bus = 0;
    orccentral::OrcSession::Settings session{};
};

// One RO module as a person describes it: its profile (name, ids, 11/29-bit, output and input registers),
// the bus it is wired to and how often its inputs are read.
struct RoModuleSettings {
    ro::RoProfile profile;
    int bus = 0;
    std::chrono::milliseconds pollPeriod{250};
};

// Which device protocols the buses carry (the module protocols beside the CS2's), saved with the station
// settings. Typed, so that no key string leaves DeviceSettings.cpp.
struct DeviceSettings {
    OrcCentralSettings orc;
    std::vector<RoModuleSettings> roModules;
    romodule::SessionTiming
        roTiming{}; // the answer timeout and retries of every module; poll period per module

    // The module named `name`, or null.
    const RoModuleSettings* roModule(const QString& name) const;
    // Whether any device protocol is on bus `bus`.
    bool usesBus(int bus) const;
    // The highest bus index a device is put on (-1: none).
    int highestBus() const;

    // The devices of the embedded demo station (sim::EmbeddedStation) on its device bus, bus 1: the
    // OpenRailCAN central and RO module "Demo RO" with the simulator's profile (ro::RoProfile::simulator(1)).
    static DeviceSettings embeddedDemo();

    // Read from and written to the group "devices" of `settings`; what cannot be read is left out.
    static DeviceSettings load(QSettings& settings);
    void save(QSettings& settings) const;
};

} // namespace stellwerk::connection
