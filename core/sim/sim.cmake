# simulated station (core/sim): a CS2 that answers like the real one (the embedded default peer).
target_sources(stellwerk-core PRIVATE
    sim/AccessoryCommands.cpp
    sim/ConfigDataService.cpp
    sim/DeviceService.cpp
    sim/FeedbackService.cpp
    sim/LocoCommands.cpp
    sim/MfxRegistry.cpp
    sim/SimulatedStation.cpp
    sim/SimulatedStation.h
    sim/StationLayout.cpp
    sim/StationState.cpp
    sim/StationStatusFiles.cpp
    sim/StatusChannels.cpp
    sim/SystemCommands.cpp
)
