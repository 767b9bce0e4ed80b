# Being connected to a station: Station → Connect... and the remembered stations, and the status bar's
# station line, start-up progress and frame counters.
target_sources(stellwerk-ui PRIVATE
    connect/ConnectDialog.cpp connect/ConnectDialog.h
    connect/ConnectionStatus.cpp connect/ConnectionStatus.h
    connect/StartupProgress.cpp connect/StartupProgress.h
    connect/StationUrlSettings.cpp connect/StationUrlSettings.h
    connect/TrafficStatus.cpp connect/TrafficStatus.h
)
