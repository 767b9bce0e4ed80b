# model sources of stellwerk-core (core/model): the railway as the UI shows it, fed by the station session.
target_sources(stellwerk-core PRIVATE
    model/Accessory.cpp
    model/CommandProblem.cpp
    model/Commands.cpp
    model/Device.cpp
    model/FeedbackContact.cpp
    model/Locomotive.cpp
    model/Programmer.cpp
    model/Programmer.h
    model/Railway.cpp
    model/Railway.h
    model/RailwayRoutes.cpp
    model/RailwayState.cpp
    model/ReadingPoller.cpp
    model/ReadingPoller.h
    model/RouteRunner.cpp
    model/RouteRunner.h
    model/RoutePlan.cpp
    model/TrackLayout.cpp
)
