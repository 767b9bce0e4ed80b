# Which protocol a frame on a bus belongs to and what it says, protocol-neutral (core/bus): pure, above
# the codecs it dispatches to.
stellwerk_core_library(bus PURE)
target_sources(stellwerk-bus PRIVATE
    bus/BusContext.cpp
    bus/BusContext.h
    bus/FrameClassifier.cpp
    bus/FrameClassifier.h
    bus/FrameDescription.cpp
    bus/FrameDescription.h
    bus/Handheld.cpp
    bus/Handheld.h
    bus/McanReading.cpp
    bus/McanReading.h
    bus/RoReading.cpp
    bus/RoReading.h
    bus/OrcReading.cpp
    bus/OrcReading.h
)
target_link_libraries(stellwerk-bus PUBLIC stellwerk-can stellwerk-ro PRIVATE stellwerk-cs2 stellwerk-mcan stellwerk-orc)
