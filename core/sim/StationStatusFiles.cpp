#include "sim/StationStatusFiles.h"

#include "cs2config/AccessoryStatusFile.h"
#include "cs2config/LocomotiveStateFile.h"
#include "sim/AccessoryCommands.h"

namespace stellwerk::sim {

std::string locomotiveStatusFile(const StationLayout& layout, const StationState& state) {
    cs2config::LocomotiveStateFile file;
    file.version = cs2config::LocomotiveStateFile::Version{};
    for (const cs2config::Locomotive& loco : layout.locomotives().locomotives) {
        if (loco.isEmpty())
            continue;
        cs2config::LocomotiveState entry;
        entry.name = loco.name;
        if (const SimulatedLoco* simulated = state.findLoco(loco.uid)) {
            entry.velocity = simulated->speed;
            entry.direction = simulated->direction == 2 ? cs2config::TravelDirection::Backward
                                                        : cs2config::TravelDirection::Forward;
            for (int f = 0; f < int(simulated->functions.size()); ++f)
                if (simulated->functions[std::size_t(f)])
                    entry.functions.push_back({f, 1, {}});
        }
        file.locomotives.push_back(std::move(entry));
    }
    return file.write().serialize();
}

std::string accessoryStatusFile(const StationLayout& layout, const StationState& state) {
    cs2config::AccessoryStatusFile file;
    file.versionMajor = 0;
    file.versionMinor = 1;
    for (const cs2config::Accessory& accessory : layout.accessories().accessories) {
        const auto position = state.accessories.find(AccessoryCommands::locIdOf(accessory));
        file.states.push_back({accessory.id, position == state.accessories.end() ? 0 : position->second, {}});
    }
    return file.write().serialize();
}

} // namespace stellwerk::sim
