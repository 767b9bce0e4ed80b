# model sources of stellwerk-model (core/model): the railway as the UI shows it, fed by the station session.
stellwerk_core_library(model)
target_sources(stellwerk-model PRIVATE
    model/Accessory.cpp
    model/BlockStates.cpp
    model/BlockStates.h
    model/CommandProblem.cpp
    model/Commands.cpp
    model/Device.cpp
    model/DeviceBindings.cpp
    model/DeviceBindings.h
    model/FeedbackContact.cpp
    model/Locomotive.cpp
    model/OccupantBook.cpp
    model/OccupantBook.h
    model/Programmer.cpp
    model/Programmer.h
    model/Railway.cpp
    model/Railway.h
    model/RailwayHandhelds.cpp
    model/RailwayDevices.cpp
    model/RailwayDevices.h
    model/RailwayHandhelds.h
    model/RailwayThrottles.cpp
    model/RailwayThrottles.h
    model/RailwayCorrections.cpp
    model/RailwayRoutes.cpp
    model/RailwayState.cpp
    model/ReadingPoller.cpp
    model/ReadingPoller.h
    model/RouteRunner.cpp
    model/RouteRunner.h
    model/RoutePlan.cpp
    model/TrackLayout.cpp
    model/UnconfirmedCommands.cpp
    model/UnconfirmedCommands.h
)
target_link_libraries(stellwerk-model PUBLIC stellwerk-cs2 stellwerk-cs2config stellwerk-station stellwerk-mcanhandhelds stellwerk-orccentral stellwerk-romodule Qt6::Core)
