# station sources of stellwerk-core (core/station): the conversation with one command station.
target_sources(stellwerk-core PRIVATE
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
    station/StationIdentity.cpp
    station/StationSession.cpp
    station/StationSession.h
    station/StationUpdates.cpp
    station/StatusDataPackets.cpp
    station/StatusDataReader.cpp
    station/StatusDataReader.h
)
