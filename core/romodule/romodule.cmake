# Stellwerk's side of RO relay/IO modules (core/romodule): one stop-and-wait session per module over a
# bus, with polling, shadow registers and offline detection. Qt Core for its timers.
stellwerk_core_library(romodule)
target_sources(stellwerk-romodule PRIVATE
    romodule/RoModuleSession.cpp
    romodule/RoModuleSession.h
)
target_link_libraries(stellwerk-romodule PUBLIC stellwerk-ro stellwerk-bus stellwerk-transport Qt6::Core)
