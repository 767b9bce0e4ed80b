# Stellwerk as the M-CAN master of MS1 handhelds (core/mcanhandhelds): logins, upgrades, polls, locomotive owners
# and stacks; protocol-free towards the railway (HandheldRailway). Qt Core for its timer and settings.
stellwerk_core_library(mcanhandhelds)
target_sources(stellwerk-mcanhandhelds PRIVATE
    mcanhandhelds/Handheld.h
    mcanhandhelds/HandheldBook.cpp
    mcanhandhelds/HandheldBook.h
    mcanhandhelds/HandheldEvent.h
    mcanhandhelds/HandheldMaster.cpp
    mcanhandhelds/HandheldMaster.h
    mcanhandhelds/HandheldRailway.h
    mcanhandhelds/HandheldWatcher.cpp
    mcanhandhelds/HandheldWatcher.h
    mcanhandhelds/LocoFacts.cpp
    mcanhandhelds/LocoFacts.h
    mcanhandhelds/LoginDesk.cpp
    mcanhandhelds/LoginDesk.h
    mcanhandhelds/MasterDesk.cpp
    mcanhandhelds/SlaveSession.cpp
    mcanhandhelds/SlaveSession.h
)
target_link_libraries(stellwerk-mcanhandhelds PUBLIC stellwerk-mcan stellwerk-can Qt6::Core)
