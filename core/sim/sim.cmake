# simulated station (core/sim): a CS2 that answers like the real one (the embedded default peer). Linked by the
# programs and tests that run one; never by stellwerk-ui or the model.
stellwerk_core_library(simulator)
target_sources(stellwerk-simulator PRIVATE
    sim/AccessoryCommands.cpp
    sim/ConfigDataService.cpp
    sim/DeviceService.cpp
    sim/EmbeddedStation.cpp
    sim/EmbeddedStation.h
    sim/FeedbackService.cpp
    sim/LocoCommands.cpp
    sim/MfxRegistry.cpp
    sim/SimulatedBus.cpp
    sim/SimulatedBus.h
    sim/SimulatedStation.cpp
    sim/SimulatedStation.h
    sim/StationLayout.cpp
    sim/StationState.cpp
    sim/StationStatusFiles.cpp
    sim/StatusChannels.cpp
    sim/SystemCommands.cpp
)
target_link_libraries(stellwerk-simulator PUBLIC stellwerk-cs2 stellwerk-cs2config stellwerk-mcan stellwerk-transport Qt6::Core Qt6::Network)
