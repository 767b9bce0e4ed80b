# Stellwerk as the M-CAN master of MS1 handhelds (core/handhelds): logins, upgrades, polls, locomotive owners
# and stacks; protocol-free towards the railway (HandheldRailway). Qt Core for its timer and settings.
stellwerk_core_library(handhelds)
target_sources(stellwerk-handhelds PRIVATE
    handhelds/Handheld.h
    handhelds/HandheldBook.cpp
    handhelds/HandheldBook.h
    handhelds/HandheldEvent.h
    handhelds/HandheldMaster.cpp
    handhelds/HandheldMaster.h
    handhelds/HandheldRailway.h
    handhelds/HandheldWatcher.cpp
    handhelds/HandheldWatcher.h
    handhelds/LocoFacts.cpp
    handhelds/LocoFacts.h
    handhelds/LoginDesk.cpp
    handhelds/LoginDesk.h
    handhelds/MasterDesk.cpp
    handhelds/SlaveSession.cpp
    handhelds/SlaveSession.h
)
target_link_libraries(stellwerk-handhelds PUBLIC stellwerk-mcan stellwerk-can Qt6::Core)
