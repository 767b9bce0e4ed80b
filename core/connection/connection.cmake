# The app's connection to one station (core/connection): transport, session, start-up and liveness in
# user terms, and the embedded simulated CS2 used when no station is configured.
target_sources(stellwerk-core PRIVATE
    connection/EmbeddedStation.cpp
    connection/EmbeddedStation.h
    connection/StationConnection.cpp
    connection/StationConnection.h
    connection/StationEndpoint.cpp
    connection/StationEndpoint.h
)
