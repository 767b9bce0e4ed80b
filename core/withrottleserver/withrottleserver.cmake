# The WiThrottle server (core/withrottleserver): Engine Driver and WiThrottle drive the railway through the
# throttle port, over TCP, with the WiThrottle codec. It needs the model and Qt Network, never a session or
# transport.
stellwerk_core_library(withrottleserver)
target_sources(stellwerk-withrottleserver PRIVATE
    withrottleserver/MdnsAnnouncement.cpp
    withrottleserver/MdnsAnnouncement.h
    withrottleserver/WiThrottleClient.cpp
    withrottleserver/WiThrottleClient.h
    withrottleserver/WiThrottleRailway.cpp
    withrottleserver/WiThrottleRailway.h
    withrottleserver/WiThrottleServer.cpp
    withrottleserver/WiThrottleServer.h
    withrottleserver/WiThrottleServerRequests.cpp
)
target_link_libraries(stellwerk-withrottleserver PUBLIC stellwerk-withrottle stellwerk-model Qt6::Core Qt6::Network)
