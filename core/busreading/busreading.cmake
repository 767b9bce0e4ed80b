# Which protocol a frame on a bus belongs to and what it says, protocol-neutral (core/busreading): pure, above
# the codecs it dispatches to.
stellwerk_core_library(busreading PURE)
target_sources(stellwerk-busreading PRIVATE
    busreading/BusContext.cpp
    busreading/BusContext.h
    busreading/FrameClassifier.cpp
    busreading/FrameClassifier.h
    busreading/FrameDescription.cpp
    busreading/FrameDescription.h
    busreading/Handheld.cpp
    busreading/Handheld.h
    busreading/McanReading.cpp
    busreading/McanReading.h
    busreading/RoReading.cpp
    busreading/RoReading.h
    busreading/OrcReading.cpp
    busreading/OrcReading.h
)
target_link_libraries(stellwerk-busreading PUBLIC stellwerk-can stellwerk-ro PRIVATE stellwerk-cs2 stellwerk-mcan stellwerk-orc)
