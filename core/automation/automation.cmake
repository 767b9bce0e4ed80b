# Automatic operation (core/automation): trains placed and tracked on the track graph, ways chosen and
# reserved, trains driven block to block. The decisions are plain C++ (Dispatcher and its parts); the
# driver (Automation) runs them on the railway model with Qt's timer.
stellwerk_core_library(automation)
target_sources(stellwerk-automation PRIVATE
    automation/Automation.cpp
    automation/Automation.h
    automation/AutomationEvent.h
    automation/Dispatcher.cpp
    automation/Dispatcher.h
    automation/DispatcherDriving.cpp
    automation/Path.h
    automation/PathChoice.cpp
    automation/PathChoice.h
    automation/Placement.h
    automation/Reservations.cpp
    automation/Reservations.h
    automation/Schedule.cpp
    automation/Schedule.h
    automation/SpeedProfile.h
    automation/StopReason.cpp
    automation/StopReason.h
    automation/Tracking.cpp
    automation/Tracking.h
    automation/Train.h
)
target_link_libraries(stellwerk-automation PUBLIC stellwerk-trackgraph stellwerk-model Qt6::Core)
