# The railway bound to the sessions of the station (core/binding): the one place where a railway model is
# made for each session, loaded with its start-up, given the layout in use and bound to the handhelds and
# the devices, for the window and the command line alike.
stellwerk_core_library(binding)
target_sources(stellwerk-binding PRIVATE
    binding/RailwayBinding.cpp
    binding/RailwayBinding.h
)
target_link_libraries(stellwerk-binding PUBLIC stellwerk-model stellwerk-connection Qt6::Core)
