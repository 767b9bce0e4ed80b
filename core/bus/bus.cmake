# The sources of stellwerk-bus (core/bus): an open CAN bus that sorts its frames by protocol and
# hands them to the sessions that subscribed.
stellwerk_core_library(bus)
target_sources(stellwerk-bus PRIVATE
    bus/Bus.cpp
    bus/Bus.h
)
target_link_libraries(stellwerk-bus PUBLIC stellwerk-busreading stellwerk-can stellwerk-transport Qt6::Core)
