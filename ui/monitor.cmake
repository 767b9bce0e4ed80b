# The bus monitor's parts beyond the panel itself: the three-way filter and the timed log replay.
target_sources(stellwerk-ui PRIVATE
    BusMonitorFilter.cpp BusMonitorFilter.h
    BusMonitorReplay.cpp BusMonitorReplay.h
)
