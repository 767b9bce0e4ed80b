# simulated station (core/sim): a CS2 that answers like the real one (the embedded default peer), MS1
# handhelds (M-CAN slaves, hence the M-CAN codec) and the bus they share. Linked by the programs and tests
# that run one; never by stellwerk-ui or the model.
stellwerk_core_library(simulator)
target_sources(stellwerk-simulator PRIVATE
    sim/AccessoryCommands.cpp
    sim/ConfigDataService.cpp
    sim/DeviceService.cpp
    sim/EmbeddedStation.cpp
    sim/EmbeddedStation.h
    sim/FeedbackService.cpp
    sim/LocoCommands.cpp
    sim/MemoryFunctions.cpp
    sim/MfxRegistry.cpp
    sim/Ms1Driver.cpp
    sim/Ms1Driver.h
    sim/Ms1Keys.cpp
    sim/Ms1Keys.h
    sim/Ms1LocoInquiry.cpp
    sim/Ms1LocoInquiry.h
    sim/Ms1Login.cpp
    sim/Ms1Login.h
    sim/Ms1MasterFrames.cpp
    sim/Ms1MasterFrames.h
    sim/Ms1Memory.cpp
    sim/Ms1Memory.h
    sim/Ms1Upgrade.cpp
    sim/Ms1Upgrade.h
    sim/SimulatedBus.cpp
    sim/SimulatedBus.h
    sim/SimulatedMs1.cpp
    sim/SimulatedMs1.h
    sim/SimulatedRoModule.cpp
    sim/SimulatedRoModule.h
    sim/SimulatedOrcDevices.cpp
    sim/SimulatedOrcDevices.h
    sim/SimulatedStation.cpp
    sim/SimulatedStation.h
    sim/StationHandhelds.cpp
    sim/StationHandhelds.h
    sim/StationLayout.cpp
    sim/StationState.cpp
    sim/StationStatusFiles.cpp
    sim/StatusChannels.cpp
    sim/SystemCommands.cpp
)
target_link_libraries(stellwerk-simulator PUBLIC stellwerk-cs2 stellwerk-cs2config stellwerk-mcanhandhelds stellwerk-mcan stellwerk-orc stellwerk-ro stellwerk-transport Qt6::Core Qt6::Network)
