# The app's connection to one station (core/connection): transport, session, start-up and liveness in
# user terms. The simulated CS2 reaches it only as a local peer from a factory (transport/LocalPeer.h).
stellwerk_core_library(connection)
target_sources(stellwerk-connection PRIVATE
    connection/ConnectionBuses.cpp
    connection/ConnectionBuses.h
    connection/ConnectionDevices.cpp
    connection/ConnectionDevices.h
    connection/ConnectionHandhelds.cpp
    connection/ConnectionHandhelds.h
    connection/DeviceSessions.cpp
    connection/DeviceSessions.h
    connection/DeviceSettings.cpp
    connection/DeviceSettings.h
    connection/HandheldConnection.cpp
    connection/HandheldConnection.h
    connection/LocomotivePictures.cpp
    connection/LocomotivePictures.h
    connection/StationAddress.cpp
    connection/StationAddress.h
    connection/StationConnection.cpp
    connection/StationConnection.h
    connection/StationEndpoint.cpp
    connection/StationEndpoint.h
    connection/StationLink.h
)
target_link_libraries(stellwerk-connection PUBLIC stellwerk-bus stellwerk-mcanhandhelds stellwerk-orccentral stellwerk-romodule stellwerk-station stellwerk-transport Qt6::Core
    Qt6::Network)
