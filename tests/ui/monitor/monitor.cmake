# The bus monitor on the embedded demo station (rows, recording), its filters, history bound and log
# replay, and the frame decoder tab.
target_sources(stellwerk-ui-tests PRIVATE
    monitor/BusMonitorBusesTest.cpp
    monitor/BusMonitorFilterTest.cpp
    monitor/BusMonitorMcanTest.cpp
    monitor/BusMonitorReplayTest.cpp
    monitor/BusMonitorTest.cpp
    monitor/FrameDecoderPanelTest.cpp
)
