# buses sources of stellwerk-buses (core/buses): an open CAN bus that sorts its frames by protocol and
# hands them to the sessions that subscribed.
stellwerk_core_library(buses)
target_sources(stellwerk-buses PRIVATE
    buses/Bus.cpp
    buses/Bus.h
)
target_link_libraries(stellwerk-buses PUBLIC stellwerk-bus stellwerk-can stellwerk-transport Qt6::Core)
