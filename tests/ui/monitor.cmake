# The bus monitor's filters, history bound and log replay.
target_sources(stellwerk-ui-tests PRIVATE
    BusMonitorFilterTest.cpp
    BusMonitorReplayTest.cpp
)
