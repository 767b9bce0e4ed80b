# Stellwerk as the OpenRailCAN central (core/orccentral): finds devices, assigns bus ids, pings, switches
# decoders, reads encoders, mirrors power and emergency stop, reports overloads, and forwards the loco
# control of ORC throttles to the CS2 through a railway interface (ThrottleBridge). Qt Core for its timers; it
# reads its bus's ORC frames and sends through the bus's transport.
stellwerk_core_library(orccentral)
target_sources(stellwerk-orccentral PRIVATE
    orccentral/DeviceRegistry.cpp
    orccentral/DeviceRegistry.h
    orccentral/OrcSession.cpp
    orccentral/OrcSession.h
    orccentral/ThrottleBridge.cpp
    orccentral/ThrottleBridge.h
)
target_link_libraries(stellwerk-orccentral PUBLIC stellwerk-orc stellwerk-bus stellwerk-can Qt6::Core)
