# station sources of stellwerk-station (core/station): the conversation with one command station.
stellwerk_core_library(station)
target_sources(stellwerk-station PRIVATE
    station/AckKey.cpp
    station/CommandTracker.cpp
    station/CommandTracker.h
    station/ConfigDownload.cpp
    station/ConfigDownload.h
    station/DeviceDescription.cpp
    station/DeviceDirectory.cpp
    station/Liveness.cpp
    station/Liveness.h
    station/StartupSequence.cpp
    station/StartupSequence.h
    station/StateQueries.cpp
    station/StateQueries.h
    station/StationIdentity.cpp
    station/StationSession.cpp
    station/StationSession.h
    station/StationUpdates.cpp
    station/StatusDataPackets.cpp
    station/StatusDataReader.cpp
    station/StatusDataReader.h
)
target_link_libraries(stellwerk-station PUBLIC stellwerk-bus stellwerk-busreading stellwerk-cs2 stellwerk-cs2config stellwerk-transport Qt6::Core)
